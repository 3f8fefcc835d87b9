// Fast facet lookup: where each facet of a simplex sits in the array of the dimension below.
//
// The kernels behind Filtration.facet_indices (and so behind every boundary and coboundary matrix of
// the library).  Rows of the lower array are hashed by their vertices read as digits in base n (the
// number of vertices); a dense table of edge indices serves triangles when n² is small.  Port of the
// numba kernels of facet_lookup.py (the same hash, probing and wrap-around integer arithmetic).
#include "arrays.hpp"

namespace thesis {

namespace {

// Fibonacci hashing of a key into a table of mask + 1 slots.  Thesis: Definition 2.18 (facets are found by key).
inline std::int64_t hash_key(std::uint64_t key, std::int64_t mask) {
    const std::uint64_t h = key * 0x9E3779B97F4A7C15ULL;
    return static_cast<std::int64_t>(h >> 20) & mask;
}

}  // namespace

// Index in lower of facet i (omitting vertex i) of every row of upper; -1 if missing.  Keys are the
// rows' vertices read as digits in base (int64 arithmetic wrapping around, as numba's did).
// Thesis: Definition 2.18 (the faces in the boundary of a simplex).
Array<std::int64_t> hashed(In<std::int64_t, nb::ndim<2>> lower, In<std::int64_t, nb::ndim<2>> upper,
                           std::int64_t base) {
    const std::int64_t m0 = static_cast<std::int64_t>(lower.shape(0));
    const std::int64_t k = static_cast<std::int64_t>(lower.shape(1));
    const std::int64_t m1 = static_cast<std::int64_t>(upper.shape(0));
    if (static_cast<std::int64_t>(upper.shape(1)) != k + 1)
        throw std::invalid_argument("hashed: upper must have one column more than lower");
    const std::int64_t* lo = lower.data();
    const std::int64_t* up = upper.data();
    const std::uint64_t ubase = static_cast<std::uint64_t>(base);
    std::vector<std::int64_t> out(static_cast<std::size_t>(m1 * (k + 1)));
    {
        nb::gil_scoped_release release;
        std::int64_t size = 1;
        while (size < 2 * m0 + 2) size *= 2;
        const std::int64_t mask = size - 1;
        std::vector<std::int64_t> keys(static_cast<std::size_t>(size), -1);
        std::vector<std::int64_t> vals(static_cast<std::size_t>(size), 0);
        for (std::int64_t r = 0; r < m0; ++r) {
            std::uint64_t key = 0;
            for (std::int64_t c = 0; c < k; ++c) key = key * ubase + static_cast<std::uint64_t>(lo[r * k + c]);
            std::int64_t h = hash_key(key, mask);
            while (keys[h] != -1) h = (h + 1) & mask;
            keys[h] = static_cast<std::int64_t>(key);
            vals[h] = r;
        }
        for (std::int64_t r = 0; r < m1; ++r) {
            const std::int64_t* row = up + r * (k + 1);
            for (std::int64_t i = 0; i < k + 1; ++i) {
                std::uint64_t ukey = 0;
                for (std::int64_t c = 0; c < k + 1; ++c)
                    if (c != i) ukey = ukey * ubase + static_cast<std::uint64_t>(row[c]);
                const std::int64_t key = static_cast<std::int64_t>(ukey);
                std::int64_t h = hash_key(ukey, mask);
                std::int64_t found = -1;
                while (keys[h] != -1) {
                    if (keys[h] == key) {
                        found = vals[h];
                        break;
                    }
                    h = (h + 1) & mask;
                }
                out[r * (k + 1) + i] = found;
            }
        }
    }
    return to_numpy(std::move(out), {static_cast<std::size_t>(m1), static_cast<std::size_t>(k + 1)});
}

// Facets of triangles through a dense n × n table of edge indices (small n: cache friendly); -1 if
// missing.  Thesis: Definition 2.18 (the boundary of a 2-simplex [a, b, c] has faces bc, ac, ab).
Array<std::int64_t> edge_table(In<std::int64_t, nb::shape<-1, 2>> edges, In<std::int64_t, nb::shape<-1, 3>> tris,
                               std::int64_t n) {
    if (n < 0 || n > 3037000499LL) throw std::invalid_argument("edge_table: n is negative or n * n overflows");
    const std::int64_t* e = edges.data();
    const std::int64_t* t = tris.data();
    const std::size_t me = edges.shape(0), mt = tris.shape(0);
    for (std::size_t k = 0; k < 2 * me; ++k)
        if (e[k] < 0 || e[k] >= n) throw std::invalid_argument("edge_table: an edge vertex is out of range");
    for (std::size_t k = 0; k < 3 * mt; ++k)
        if (t[k] < 0 || t[k] >= n) throw std::invalid_argument("edge_table: a triangle vertex is out of range");
    std::vector<std::int64_t> out(3 * mt);
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> table(static_cast<std::size_t>(n * n), -1);
        for (std::size_t r = 0; r < me; ++r) table[e[2 * r] * n + e[2 * r + 1]] = static_cast<std::int64_t>(r);
        for (std::size_t r = 0; r < mt; ++r) {
            const std::int64_t a = t[3 * r], b = t[3 * r + 1], c = t[3 * r + 2];
            out[3 * r] = table[b * n + c];
            out[3 * r + 1] = table[a * n + c];
            out[3 * r + 2] = table[a * n + b];
        }
    }
    return to_numpy(std::move(out), {mt, 3});
}

}  // namespace thesis

NB_MODULE(facet_lookup, m) {
    namespace nb = nanobind;
    m.doc() = "Where each facet of a simplex sits in the array of the dimension below (thesis Definition 2.18).";
    m.def("hashed", &thesis::hashed, nb::arg("lower"), nb::arg("upper"), nb::arg("base"),
          "Index in lower of facet i (omitting vertex i) of every row of upper; -1 if missing.");
    m.def("edge_table", &thesis::edge_table, nb::arg("edges"), nb::arg("tris"), nb::arg("n"),
          "Facets of triangles through a dense n x n table of edge indices; -1 if missing.");
}
