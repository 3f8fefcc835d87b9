// The face levels and attached values of the alpha complex (thesis Definition 2.14 and §2.1.2): the port
// of _facet_ids and _coface_min (thesis_lib/complexes/alpha.py).
#include "arrays.hpp"
#include "geometry_arrays.hpp"

#include <nanobind/stl/tuple.h>

#include <limits>
#include <tuple>

namespace thesis {

// Number the facets of a triangulation from its neighbours nb (m, d + 1): ids[s, i] for the facet
// opposite vertex i of simplex s (both occurrences of an interior facet get the same id), and one
// (s, i) per id.  Thesis: Definition 2.13 (the Delaunay complex's (d − 1)-simplices).
std::tuple<Array<std::int64_t>, Array<std::int64_t>, Array<std::int64_t>> facet_ids(
    In<std::int64_t, nb::ndim<2>> neighbours) {
    const std::size_t m = neighbours.shape(0), w = neighbours.shape(1);
    const std::int64_t* N = neighbours.data();
    for (std::size_t i = 0; i < neighbours.size(); ++i) {
        if (N[i] >= static_cast<std::int64_t>(m)) {
            throw std::invalid_argument("nb: neighbour " + std::to_string(N[i]) + " out of range (" +
                                        std::to_string(m) + " simplices)");
        }
    }
    std::vector<std::int64_t> ids(m * w, -1), rep_s, rep_i;
    {
        nb::gil_scoped_release release;
        rep_s.reserve(m * w);
        rep_i.reserve(m * w);
        std::int64_t count = 0;
        for (std::size_t s = 0; s < m; ++s) {
            for (std::size_t i = 0; i < w; ++i) {
                if (ids[s * w + i] >= 0) continue;
                ids[s * w + i] = count;
                rep_s.push_back(static_cast<std::int64_t>(s));
                rep_i.push_back(static_cast<std::int64_t>(i));
                const std::int64_t t = N[s * w + i];
                if (t >= 0) {
                    for (std::size_t j = 0; j < w; ++j) {
                        if (N[t * w + j] == static_cast<std::int64_t>(s)) {
                            ids[t * w + j] = count;
                            break;
                        }
                    }
                }
                ++count;
            }
        }
    }
    return {to_numpy(std::move(ids), {m, w}), to_numpy(std::move(rep_s)), to_numpy(std::move(rep_i))};
}

// For each of the `size` faces, the smallest value among the cofaces listing it in fidx (inf if none).
// Thesis: Definition 2.14 (an attached simplex enters with its first coface).
Array<double> coface_min(In<std::int64_t, nb::ndim<2>> fidx, In<double, nb::ndim<1>> values, std::int64_t size) {
    const std::size_t m = fidx.shape(0), w = fidx.shape(1);
    if (size < 0) throw std::invalid_argument("size: must be >= 0, got " + std::to_string(size));
    check_size(values.shape(0), m, "values: length (the number of cofaces)");
    check_indices(fidx.data(), fidx.size(), static_cast<std::size_t>(size), "fidx");
    std::vector<double> out(static_cast<std::size_t>(size), std::numeric_limits<double>::infinity());
    {
        nb::gil_scoped_release release;
        const std::int64_t* F = fidx.data();
        const double* V = values.data();
        for (std::size_t r = 0; r < m; ++r) {
            const double v = V[r];
            for (std::size_t i = 0; i < w; ++i) {
                const std::int64_t f = F[r * w + i];
                if (v < out[f]) out[f] = v;
            }
        }
    }
    return to_numpy(std::move(out));
}

}  // namespace thesis

NB_MODULE(alpha_complex, m) {
    namespace nb = nanobind;
    m.doc() = "Facet numbering and coface minima of the alpha complex (thesis Definition 2.14, §2.1.2).";
    m.def("facet_ids", &thesis::facet_ids, nb::arg("nb"));
    m.def("coface_min", &thesis::coface_min, nb::arg("fidx"), nb::arg("values"), nb::arg("size"));
}
