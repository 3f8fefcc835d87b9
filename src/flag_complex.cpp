// Flag complexes of weighted graphs: the edge lists of Rips complexes and the clique expansion.
//
// A graph is stored as an "upper" CSR structure: for every vertex v the sorted neighbours u > v
// (indices[indptr[v]:indptr[v + 1]]) and the edge values in the same places.  A level of the
// expansion turns the d-simplices (rows sorted ascending, rows in lexicographic order) into the
// (d + 1)-simplices that are cliques, again in lexicographic order, with value = the maximum of the
// parent's value and the new edges' values.  Port of the numba kernels of complexes/_flag.py,
// operation by operation (the same comparisons in the same order, so the same bytes).
#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "arrays.hpp"

namespace thesis {

using Edges = std::tuple<Array<std::int64_t>, Array<double>>;

// The first position in arr[lo:hi] whose entry is not below x (arr sorted there).
// Thesis: §2.1.2 (a clique is found by intersecting sorted neighbour lists).
inline std::int64_t lower_bound_in(const std::int64_t* arr, std::int64_t lo, std::int64_t hi, std::int64_t x) {
    while (lo < hi) {
        std::int64_t mid = (lo + hi) >> 1;
        if (arr[mid] < x) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return lo;
}

// Pairs i < j with |p_i - p_j| <= threshold (lexicographic) and their lengths, by brute force.
// Thesis: Definition 2.11 (the edges of R(X, ε): pairs at distance ≤ 2ε).
Edges pairwise_edges(In<double, nb::ndim<2>> points, double threshold) {
    const auto P = points.view();
    const std::int64_t n = static_cast<std::int64_t>(points.shape(0));
    const std::int64_t dim = static_cast<std::int64_t>(points.shape(1));
    std::vector<std::int64_t> out;
    std::vector<double> out_v;
    {
        nb::gil_scoped_release release;
        const double t2 = threshold * threshold;
        const double bound = t2 * (1.0 + 1e-12) + 1e-300;
        for (std::int64_t i = 0; i < n; ++i) {
            for (std::int64_t j = i + 1; j < n; ++j) {
                double s = 0.0;
                for (std::int64_t k = 0; k < dim; ++k) {
                    const double diff = P(i, k) - P(j, k);
                    s += diff * diff;
                }
                if (s <= bound) {
                    const double length = std::sqrt(s);
                    if (length <= threshold) {
                        out.push_back(i);
                        out.push_back(j);
                        out_v.push_back(length);
                    }
                }
            }
        }
    }
    const std::size_t count = out_v.size();
    return {to_numpy(std::move(out), {count, 2}), to_numpy(std::move(out_v))};
}

// Pairs i < j with matrix[i, j] <= threshold (lexicographic) and their entries.
// Thesis: Definition 2.11 (R(X, ε) needs only the pairwise distances).
Edges matrix_edges(In<double, nb::ndim<2>> matrix, double threshold) {
    const std::int64_t n = static_cast<std::int64_t>(matrix.shape(0));
    if (matrix.shape(1) < matrix.shape(0))
        throw std::invalid_argument("matrix_edges: the matrix has fewer columns than rows");
    const auto M = matrix.view();
    std::vector<std::int64_t> out;
    std::vector<double> out_v;
    {
        nb::gil_scoped_release release;
        for (std::int64_t i = 0; i < n; ++i) {
            for (std::int64_t j = i + 1; j < n; ++j) {
                const double v = M(i, j);
                if (v <= threshold) {
                    out.push_back(i);
                    out.push_back(j);
                    out_v.push_back(v);
                }
            }
        }
    }
    const std::size_t count = out_v.size();
    return {to_numpy(std::move(out), {count, 2}), to_numpy(std::move(out_v))};
}

// All cliques one dimension up from the parents (d-simplices, lexicographic), with value the maximum
// of the parent's value and the values of the edges to the new vertex; lexicographic again.
// Thesis: §2.1.2 (the Rips complex is a flag complex: its 1-skeleton determines it).
Edges expand_level(In<std::int64_t, nb::ndim<2>> parents, In<double, nb::ndim<1>> parent_vals,
                   In<std::int64_t, nb::ndim<1>> indptr, In<std::int64_t, nb::ndim<1>> indices,
                   In<double, nb::ndim<1>> edge_vals) {
    const std::int64_t m = static_cast<std::int64_t>(parents.shape(0));
    const std::int64_t width = static_cast<std::int64_t>(parents.shape(1));
    if (width < 1) throw std::invalid_argument("expand_level: parents must have at least one column");
    if (parent_vals.shape(0) != parents.shape(0))
        throw std::invalid_argument("expand_level: parent_vals must have one value per parent");
    if (indptr.shape(0) < 1) throw std::invalid_argument("expand_level: indptr must not be empty");
    if (edge_vals.shape(0) != indices.shape(0))
        throw std::invalid_argument("expand_level: edge_vals must have one value per entry of indices");
    const std::int64_t n = static_cast<std::int64_t>(indptr.shape(0)) - 1;
    const std::int64_t nnz = static_cast<std::int64_t>(indices.shape(0));
    const std::int64_t* ip = indptr.data();
    const std::int64_t* ind = indices.data();
    const double* ev = edge_vals.data();
    const std::int64_t* par = parents.data();
    const double* pv = parent_vals.data();
    if (ip[0] < 0) throw std::invalid_argument("expand_level: indptr[0] is negative");
    for (std::int64_t v = 0; v < n; ++v)
        if (ip[v + 1] < ip[v]) throw std::invalid_argument("expand_level: indptr is not non-decreasing");
    if (ip[n] > nnz) throw std::invalid_argument("expand_level: indptr points past the end of indices");
    for (std::int64_t k = 0; k < m * width; ++k)
        if (par[k] < 0 || par[k] >= n) throw std::invalid_argument("expand_level: a parent vertex is out of range");

    std::vector<std::int64_t> out;
    std::vector<double> out_v;
    {
        nb::gil_scoped_release release;
        // at most one child per upper neighbour of a parent's last vertex: reserve that once (pages
        // not written are never touched), so the buffers do not regrow level after level
        std::int64_t bound = 0;
        for (std::int64_t r = 0; r < m; ++r) {
            const std::int64_t last = par[r * width + width - 1];
            bound += ip[last + 1] - ip[last];
        }
        bound = std::min<std::int64_t>(bound, std::int64_t(1) << 22);
        out.reserve(static_cast<std::size_t>(bound * (width + 1)));
        out_v.reserve(static_cast<std::size_t>(bound));
        std::vector<std::int64_t> ptr(static_cast<std::size_t>(width)), ends(static_cast<std::size_t>(width));
        for (std::int64_t r = 0; r < m; ++r) {
            const std::int64_t* row = par + r * width;
            const std::int64_t last = row[width - 1];
            const std::int64_t start_last = ip[last];
            const std::int64_t end_last = ip[last + 1];
            if (start_last == end_last) continue;
            const std::int64_t first_cand = ind[start_last];
            bool ok = true;
            for (std::int64_t i = 0; i < width - 1; ++i) {
                const std::int64_t v = row[i];
                ptr[i] = lower_bound_in(ind, ip[v], ip[v + 1], first_cand);
                ends[i] = ip[v + 1];
                if (ptr[i] == ends[i]) {
                    ok = false;
                    break;
                }
            }
            if (!ok) continue;
            const double base = pv[r];
            for (std::int64_t q = start_last; q < end_last; ++q) {
                const std::int64_t w = ind[q];
                double val = ev[q] > base ? ev[q] : base;  // Python's max(base, edge_vals[q])
                bool found = true;
                for (std::int64_t i = 0; i < width - 1; ++i) {
                    std::int64_t p = ptr[i];
                    const std::int64_t e = ends[i];
                    while (p < e && ind[p] < w) ++p;
                    ptr[i] = p;
                    if (p == e) {
                        found = false;
                        ok = false;
                        break;
                    }
                    if (ind[p] != w) {
                        found = false;
                        break;
                    }
                    if (ev[p] > val) val = ev[p];
                }
                if (!ok) break;
                if (found) {
                    for (std::int64_t i = 0; i < width; ++i) out.push_back(row[i]);
                    out.push_back(w);
                    out_v.push_back(val);
                }
            }
        }
    }
    const std::size_t count = out_v.size();
    return {to_numpy(std::move(out), {count, static_cast<std::size_t>(width + 1)}), to_numpy(std::move(out_v))};
}

}  // namespace thesis

NB_MODULE(flag_complex, m) {
    namespace nb = nanobind;
    m.doc() = "Edge lists of Rips complexes and the flag (clique) expansion (thesis Definition 2.11, §2.1.2).";
    m.def("pairwise_edges", &thesis::pairwise_edges, nb::arg("points"), nb::arg("threshold"),
          "Pairs i < j with |p_i - p_j| <= threshold (lexicographic) and their lengths.");
    m.def("matrix_edges", &thesis::matrix_edges, nb::arg("matrix"), nb::arg("threshold"),
          "Pairs i < j with matrix[i, j] <= threshold (lexicographic) and their entries.");
    m.def("expand_level", &thesis::expand_level, nb::arg("parents"), nb::arg("parent_vals"), nb::arg("indptr"),
          nb::arg("indices"), nb::arg("edge_vals"),
          "All cliques one dimension up from parents; returns (children, values).");
}
