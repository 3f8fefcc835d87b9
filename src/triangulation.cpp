// The neighbour pairing of the candidate regular triangulation (thesis Definition 2.13, §2.1.2): the
// port of _hint_pairs (thesis_lib/complexes/triangulation.py), which checks the facet pairs Qhull
// claims before the certificate trusts them.
#include "arrays.hpp"
#include "geometry_arrays.hpp"

#include <nanobind/stl/tuple.h>

#include <tuple>

namespace thesis {

// Facet pairs claimed by hint (s1 < s2), checked: the back pointer exists and the facets have the same
// vertices.  Returns (s1, i1, s2, i2, ok) with one row per claimed pair.
// Thesis: Definition 2.13 (the Delaunay complex; neighbouring simplices share a facet).
std::tuple<Array<std::int64_t>, Array<std::int64_t>, Array<std::int64_t>, Array<std::int64_t>, Array<bool>>
hint_pairs(In<std::int64_t, nb::ndim<2>> tri, In<std::int64_t, nb::ndim<2>> hint) {
    const std::size_t m = tri.shape(0), w = tri.shape(1);
    check_size(hint.shape(0), m, "hint: rows (the number of simplices)");
    check_size(hint.shape(1), w, "hint: columns (the simplices' width)");
    const std::int64_t* T = tri.data();
    const std::int64_t* H = hint.data();
    for (std::size_t i = 0; i < hint.size(); ++i) {
        if (H[i] >= static_cast<std::int64_t>(m)) {
            throw std::invalid_argument("hint: neighbour " + std::to_string(H[i]) + " out of range (" +
                                        std::to_string(m) + " simplices)");
        }
    }
    std::vector<std::int64_t> s1, i1, s2, i2;
    std::unique_ptr<bool[]> ok;
    std::size_t count = 0;
    {
        nb::gil_scoped_release release;
        for (std::size_t s = 0; s < m; ++s)
            for (std::size_t i = 0; i < w; ++i)
                if (H[s * w + i] > static_cast<std::int64_t>(s)) ++count;
        s1.resize(count);
        i1.resize(count);
        s2.resize(count);
        i2.resize(count);
        ok = bool_buffer(count);
        std::size_t r = 0;
        for (std::size_t s = 0; s < m; ++s) {
            for (std::size_t i = 0; i < w; ++i) {
                const std::int64_t t = H[s * w + i];
                if (t <= static_cast<std::int64_t>(s)) continue;
                s1[r] = static_cast<std::int64_t>(s);
                i1[r] = static_cast<std::int64_t>(i);
                s2[r] = t;
                i2[r] = 0;
                for (std::size_t j = 0; j < w; ++j) {
                    if (H[t * w + j] == static_cast<std::int64_t>(s)) {
                        i2[r] = static_cast<std::int64_t>(j);
                        bool good = true;
                        std::size_t a = 0, b = 0;
                        for (std::size_t step = 0; step + 1 < w; ++step) {
                            if (a == i) ++a;
                            if (b == j) ++b;
                            if (T[s * w + a] != T[t * w + b]) good = false;
                            ++a;
                            ++b;
                        }
                        ok[r] = good;
                        break;
                    }
                }
                ++r;
            }
        }
    }
    return {to_numpy(std::move(s1)), to_numpy(std::move(i1)), to_numpy(std::move(s2)), to_numpy(std::move(i2)),
            to_numpy(std::move(ok), count)};
}

}  // namespace thesis

NB_MODULE(triangulation, m) {
    namespace nb = nanobind;
    m.doc() = "The facet pairing of the candidate regular triangulation (thesis Definition 2.13, §2.1.2).";
    m.def("hint_pairs", &thesis::hint_pairs, nb::arg("tri"), nb::arg("hint"));
}
