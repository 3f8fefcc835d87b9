// The explicit persistence engine's kernels (port of persistence/engine.py): H0 by union–find with the
// elder rule, and the coboundary matrix of one dimension assembled as compressed sparse columns,
// which reduction.cpp then reduces (cohomology with clearing).
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "arrays.hpp"
#include "union_find.hpp"

namespace thesis {

using I64 = Array<std::int64_t>;
using Coboundary = std::tuple<I64, Array<std::int32_t>, Array<std::int8_t>, I64, I64>;

// A new one-dimensional NumPy bool array owning the bytes (each 0 or 1).
// Thesis: §2.3.5 (the cleared columns of the reduction are marked in such a mask).
Array<bool> bool_array(std::vector<std::uint8_t>&& v) {
    auto* owned = new std::vector<std::uint8_t>(std::move(v));
    nb::capsule owner(owned, [](void* q) noexcept { delete static_cast<std::vector<std::uint8_t>*>(q); });
    const std::size_t shape[1] = {owned->size()};
    return Array<bool>(reinterpret_cast<bool*>(owned->data()), 1, shape, owner);
}

// The columns of δ on m_d simplices being assembled: offsets from per-column counts, then a fill pass
// that writes each entry and keeps each column's pivot, its earliest coface (value, then index).
// Thesis: Definition 2.18 (the sign (−1)^i of the facet omitting vertex i), §2.3.5 (the pivot).
struct Columns {
    std::vector<std::int64_t> indptr, fill, pivot, pivot_sign;
    std::vector<std::int32_t> rows;
    std::vector<std::int8_t> signs;
    std::vector<double> pivot_value;

    // Turn the counts indptr[c + 1] into offsets and allocate the columns, no pivot found yet.
    void allocate(std::int64_t m_d) {
        for (std::int64_t c = 0; c < m_d; ++c) indptr[c + 1] += indptr[c];
        fill.assign(indptr.begin(), indptr.end() - 1);
        rows.resize(static_cast<std::size_t>(indptr[m_d]));
        signs.resize(static_cast<std::size_t>(indptr[m_d]));
        pivot.assign(static_cast<std::size_t>(m_d), -1);
        pivot_sign.assign(static_cast<std::size_t>(m_d), 0);
        pivot_value.assign(static_cast<std::size_t>(m_d), std::numeric_limits<double>::infinity());
    }

    // Raw views of the columns for the fill pass (locals the compiler keeps in registers: an int8 store
    // may alias anything, so member vectors would be reloaded after every entry).
    struct Fill {
        std::int64_t* fill;
        std::int32_t* rows;
        std::int8_t* signs;
        std::int64_t* pivot;
        std::int64_t* pivot_sign;
        double* pivot_value;

        // The entry (coface t of value v, facet position i) of column c.
        void put(std::int64_t c, std::int64_t t, double v, std::int64_t i) const {
            const std::int8_t s = static_cast<std::int8_t>(1 - 2 * (i & 1));
            const std::int64_t at = fill[c];
            rows[at] = static_cast<std::int32_t>(t);
            signs[at] = s;
            fill[c] = at + 1;
            if (pivot[c] == -1 || v < pivot_value[c]) {  // t ascending: ties keep the smaller index
                pivot[c] = t;
                pivot_sign[c] = s;
                pivot_value[c] = v;
            }
        }
    };

    Fill filler() {
        return {fill.data(), rows.data(), signs.data(), pivot.data(), pivot_sign.data(), pivot_value.data()};
    }

    Coboundary release() {
        return {to_numpy(std::move(indptr)), to_numpy(std::move(rows)), to_numpy(std::move(signs)),
                to_numpy(std::move(pivot)), to_numpy(std::move(pivot_sign))};
    }
};

// Compressed columns of δ on the d-simplices: facets[t, i] is the d-simplex omitting vertex i of the
// (d+1)-simplex t; rows are coface indices (sorted within a column), pivot = earliest coface.
// Returns (indptr, rows, signs, pivot, pivot_sign).
// Thesis: Definition 2.18 (boundary with signs), its transpose the coboundary of §2.3.5.
Coboundary coboundary(In<std::int64_t, nb::ndim<2>> facets_a, In<double, nb::ndim<1>> up_values_a, std::int64_t m_d) {
    const std::int64_t m_up = static_cast<std::int64_t>(facets_a.shape(0)), w = static_cast<std::int64_t>(facets_a.shape(1));
    if (m_d < 0 || m_d > std::numeric_limits<std::int32_t>::max() || m_up > std::numeric_limits<std::int32_t>::max())
        throw std::invalid_argument("coboundary: more than 2**31 - 1 simplices in one dimension");
    if (static_cast<std::int64_t>(up_values_a.shape(0)) != m_up)
        throw std::invalid_argument("coboundary: up_values must have one value per coface");
    const std::int64_t* facets = facets_a.data();
    const double* up_values = up_values_a.data();
    Columns col;
    bool out_of_range = false;
    {
        nb::gil_scoped_release release;
        col.indptr.assign(static_cast<std::size_t>(m_d + 1), 0);
        std::int64_t* count = col.indptr.data() + 1;
        for (std::int64_t e = 0; e < m_up * w; ++e) {  // the counting pass checks every facet index
            const std::int64_t f = facets[e];
            if (f < 0 || f >= m_d) {
                out_of_range = true;
                break;
            }
            ++count[f];
        }
        if (!out_of_range) {
            col.allocate(m_d);
            const auto put = col.filler();
            for (std::int64_t t = 0; t < m_up; ++t) {
                const double v = up_values[t];
                for (std::int64_t i = 0; i < w; ++i) put.put(facets[t * w + i], t, v, i);
            }
        }
    }
    if (out_of_range) throw std::invalid_argument("coboundary: a facet index is out of range");
    return col.release();
}

// coboundary() of the edges, fused with a dense n × n edge table for the triangles' facets (no facet
// array at all).  Returns (indptr, rows, signs, pivot, pivot_sign, bad): bad = −1, or the first
// triangle with an edge missing from edges (then the arrays are empty and meaningless).
// Thesis: Definition 2.18, §2.3.5.
std::tuple<I64, Array<std::int32_t>, Array<std::int8_t>, I64, I64, std::int64_t> coboundary_triangles(
    In<std::int64_t, nb::ndim<2>> edges_a, In<std::int64_t, nb::ndim<2>> tris_a, std::int64_t n,
    In<double, nb::ndim<1>> up_values_a) {
    const std::int64_t m_d = static_cast<std::int64_t>(edges_a.shape(0));
    const std::int64_t m_up = static_cast<std::int64_t>(tris_a.shape(0));
    if (edges_a.shape(1) != 2 || tris_a.shape(1) != 3)
        throw std::invalid_argument("coboundary_triangles: edges must have 2 columns and triangles 3");
    if (m_d > std::numeric_limits<std::int32_t>::max() || m_up > std::numeric_limits<std::int32_t>::max())
        throw std::invalid_argument("coboundary_triangles: more than 2**31 - 1 simplices in one dimension");
    if (n < 0 || n > (std::int64_t(1) << 31)) throw std::invalid_argument("coboundary_triangles: n is out of range");
    if (static_cast<std::int64_t>(up_values_a.shape(0)) != m_up)
        throw std::invalid_argument("coboundary_triangles: up_values must have one value per triangle");
    const std::int64_t* edges = edges_a.data();
    const std::int64_t* tris = tris_a.data();
    const double* up_values = up_values_a.data();
    for (std::int64_t e = 0; e < 2 * m_d; ++e)
        if (edges[e] < 0 || edges[e] >= n) throw std::invalid_argument("coboundary_triangles: a vertex is out of range");
    for (std::int64_t e = 0; e < 3 * m_up; ++e)
        if (tris[e] < 0 || tris[e] >= n) throw std::invalid_argument("coboundary_triangles: a vertex is out of range");
    Columns col;
    std::int64_t bad = -1;
    {
        nb::gil_scoped_release release;
        std::vector<std::int32_t> table(static_cast<std::size_t>(n * n), -1);
        for (std::int64_t r = 0; r < m_d; ++r) table[edges[2 * r] * n + edges[2 * r + 1]] = static_cast<std::int32_t>(r);
        col.indptr.assign(static_cast<std::size_t>(m_d + 1), 0);
        for (std::int64_t t = 0; t < m_up && bad < 0; ++t) {
            const std::int64_t a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
            const std::int32_t e0 = table[b * n + c], e1 = table[a * n + c], e2 = table[a * n + b];
            if (e0 < 0 || e1 < 0 || e2 < 0) {
                bad = t;
                break;
            }
            ++col.indptr[e0 + 1];
            ++col.indptr[e1 + 1];
            ++col.indptr[e2 + 1];
        }
        if (bad < 0) {
            col.allocate(m_d);
            const auto put = col.filler();
            for (std::int64_t t = 0; t < m_up; ++t) {
                const double v = up_values[t];
                const std::int64_t a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
                put.put(table[b * n + c], t, v, 0);
                put.put(table[a * n + c], t, v, 1);
                put.put(table[a * n + b], t, v, 2);
            }
        } else {
            col = Columns();
        }
    }
    auto [indptr, rows, signs, pivot, pivot_sign] = col.release();
    return {indptr, rows, signs, pivot, pivot_sign, bad};
}

// Elder-rule union–find over the edges in filtration order (order1: edge indices; vrank: each vertex's
// position in the vertex order).  Returns (dying vertices, their killing edges, negative-edge mask,
// essential vertices): the pairs Reduce finds on the edge columns.
// Thesis: Definition 2.31 (the elder rule), §2.3.4.
std::tuple<I64, I64, Array<bool>, I64> h0(In<std::int64_t, nb::ndim<2>> edge_facets_a, In<std::int64_t, nb::ndim<1>> vrank_a,
                                          In<std::int64_t, nb::ndim<1>> order1_a) {
    const std::int64_t n = static_cast<std::int64_t>(vrank_a.shape(0));
    const std::int64_t m1 = static_cast<std::int64_t>(order1_a.shape(0));
    const std::int64_t m_e = static_cast<std::int64_t>(edge_facets_a.shape(0));
    if (edge_facets_a.shape(1) != 2) throw std::invalid_argument("h0: edge_facets must have 2 columns");
    const std::int64_t* ef = edge_facets_a.data();
    const std::int64_t* vrank = vrank_a.data();
    const std::int64_t* order1 = order1_a.data();
    for (std::int64_t e = 0; e < 2 * m_e; ++e)
        if (ef[e] < 0 || ef[e] >= n) throw std::invalid_argument("h0: a vertex index is out of range");
    for (std::int64_t r = 0; r < m1; ++r)
        if (order1[r] < 0 || order1[r] >= m1 || order1[r] >= m_e) throw std::invalid_argument("h0: an edge index is out of range");
    std::vector<std::int64_t> pv, pe, ess;
    std::vector<std::uint8_t> negative(static_cast<std::size_t>(m1), 0);
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> parent(static_cast<std::size_t>(n));
        for (std::int64_t v = 0; v < n; ++v) parent[v] = v;
        for (std::int64_t r = 0; r < m1; ++r) {
            const std::int64_t e = order1[r];
            std::int64_t a = find(parent.data(), ef[2 * e]);
            std::int64_t b = find(parent.data(), ef[2 * e + 1]);
            if (a == b) continue;
            if (vrank[a] > vrank[b]) std::swap(a, b);  // a is younger: it dies
            parent[b] = a;  // b (the younger root) joins the elder a
            pv.push_back(b);
            pe.push_back(e);
            negative[e] = 1;
        }
        for (std::int64_t v = 0; v < n; ++v)
            if (parent[v] == v) ess.push_back(v);
    }
    return {to_numpy(std::move(pv)), to_numpy(std::move(pe)), bool_array(std::move(negative)), to_numpy(std::move(ess))};
}

}  // namespace thesis

NB_MODULE(explicit_cohomology, m) {
    m.doc() = "The explicit persistence engine's kernels: H0 by union-find, coboundary matrices (thesis §2.3.5).";
    m.def("coboundary", &thesis::coboundary, nanobind::arg("facets"), nanobind::arg("up_values"), nanobind::arg("m_d"));
    m.def("coboundary_triangles", &thesis::coboundary_triangles, nanobind::arg("edges"), nanobind::arg("tris"),
          nanobind::arg("n"), nanobind::arg("up_values"));
    m.def("h0", &thesis::h0, nanobind::arg("edge_facets"), nanobind::arg("vrank"), nanobind::arg("order1"));
}
