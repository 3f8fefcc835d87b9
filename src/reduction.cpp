// The stored-matrix column reduction mod p, with clearing: the library's one reduction of a matrix
// held in compressed columns (port of persistence/kernels.py's reduce_columns).
//
// It serves the explicit engine (coboundary columns: cohomology), the persistence of a filtered
// chain complex (boundary columns: the Morse reduction) and the representative cycles (which read
// the reduced columns R or the chains V off its record).
#include <nanobind/stl/tuple.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "arrays.hpp"
#include "column_heap.hpp"

namespace thesis {

// What reduce_columns keeps of a reduced column (the same numbers as kernels.py's KEEP_*): its chain
// V (cohomology), V also of the columns that reduce to zero (representatives), or the reduced column.
constexpr int KEEP_V = 0, KEEP_V_ALL = 1, KEEP_REDUCED = 2;

using I64 = Array<std::int64_t>;
using Reduction = std::tuple<I64, I64, I64, std::int64_t, I64, I64, I64, I64>;

// The columns to reduce (in that order) and the state of every column of the matrix: cleared (to be
// skipped), its pivot (least row, −1 when empty) and the coefficient there.
struct ColumnState {
    In<std::int64_t, nb::ndim<1>> columns;
    In<bool, nb::ndim<1>> cleared;
    In<std::int64_t, nb::ndim<1>> pivot, pivot_coef;
};

// Reduce the columns `columns` (in that order) of the CSC matrix (indptr, rows, coefs) over Z/p, rows
// ordered by (row_value[r], r), pivot = least row; cleared columns are skipped, a column whose pivot
// is free is paired untouched, a colliding column is reduced lazily on a heap (Bauer 2021) by adding
// earlier columns, regenerated from their chains V (KEEP_V, KEEP_V_ALL) or read from their stored
// reduced columns (KEEP_REDUCED).  Returns (pair columns, pair rows, zero columns, additions, start,
// length, pool keys, pool coefficients) exactly as kernels.reduce_columns documents them.
// Thesis: Algorithm 1 (Reduce) inside Algorithm 2 (ComputeIntervals), §2.3.5.
template <class R, class C>
Reduction reduce_columns(In<std::int64_t, nb::ndim<1>> indptr_a, In<R, nb::ndim<1>> rows_a,
                         In<C, nb::ndim<1>> coefs_a, In<double, nb::ndim<1>> row_value_a, const ColumnState& state,
                         std::int64_t p, int keep) {
    const In<std::int64_t, nb::ndim<1>>& columns_a = state.columns;
    const In<bool, nb::ndim<1>>& cleared_a = state.cleared;
    const In<std::int64_t, nb::ndim<1>>& pivot_a = state.pivot;
    const In<std::int64_t, nb::ndim<1>>& pivot_coef_a = state.pivot_coef;
    // ---- the shapes and indices, checked once (the rows of an entry where it is read)
    if (indptr_a.shape(0) < 1) throw std::invalid_argument("reduce_columns: indptr must have m + 1 >= 1 entries");
    const std::int64_t m = static_cast<std::int64_t>(indptr_a.shape(0)) - 1;
    const std::int64_t nrows = static_cast<std::int64_t>(row_value_a.shape(0));
    const std::int64_t ncols = static_cast<std::int64_t>(columns_a.shape(0));
    if (p < 2 || p >= (std::int64_t(1) << 31)) throw std::invalid_argument("reduce_columns: p must be in 2 .. 2**31 - 1");
    if (keep != KEEP_V && keep != KEEP_V_ALL && keep != KEEP_REDUCED)
        throw std::invalid_argument("reduce_columns: keep must be KEEP_V, KEEP_V_ALL or KEEP_REDUCED");
    if (m > std::numeric_limits<std::int32_t>::max())
        throw std::invalid_argument("reduce_columns: more than 2**31 - 1 columns");
    if (static_cast<std::int64_t>(cleared_a.shape(0)) != m || static_cast<std::int64_t>(pivot_a.shape(0)) != m ||
        static_cast<std::int64_t>(pivot_coef_a.shape(0)) != m)
        throw std::invalid_argument("reduce_columns: cleared, pivot and pivot_coef must have one entry per column");
    const std::int64_t* indptr = indptr_a.data();
    const R* rows = rows_a.data();
    const C* coefs = coefs_a.data();
    const double* row_value = row_value_a.data();
    const std::int64_t* columns = columns_a.data();
    const bool* cleared = cleared_a.data();
    const std::int64_t* pivot = pivot_a.data();
    const std::int64_t* pivot_coef = pivot_coef_a.data();
    const std::int64_t nnz = std::min(static_cast<std::int64_t>(rows_a.shape(0)),
                                      static_cast<std::int64_t>(coefs_a.shape(0)));
    if (indptr[0] < 0) throw std::invalid_argument("reduce_columns: indptr[0] is negative");
    for (std::int64_t c = 0; c < m; ++c)
        if (indptr[c + 1] < indptr[c]) throw std::invalid_argument("reduce_columns: indptr is not non-decreasing");
    if (indptr[m] > nnz) throw std::invalid_argument("reduce_columns: indptr addresses entries beyond rows/coefs");
    for (std::int64_t i = 0; i < ncols; ++i)
        if (columns[i] < 0 || columns[i] >= m) throw std::invalid_argument("reduce_columns: a column index is out of range");
    for (std::int64_t c = 0; c < m; ++c)
        if (pivot[c] < -1 || pivot[c] >= nrows) throw std::invalid_argument("reduce_columns: a pivot row is out of range");

    std::vector<std::int64_t> pair_c, pair_r, zero, vstart, vlen, pool_k, pool_c;
    std::int64_t additions = 0;
    {
        nb::gil_scoped_release release;
        // a column's rows are checked when they are first read (most columns are paired untouched)
        auto row_at = [&](std::int64_t e) -> std::int64_t {
            const std::int64_t r = static_cast<std::int64_t>(rows[e]);
            if (r < 0 || r >= nrows) throw std::invalid_argument("reduce_columns: a row index is out of range");
            return r;
        };
        std::vector<std::int32_t> owner(static_cast<std::size_t>(nrows), -1);  // the column owning each pivot
        std::vector<std::int64_t> pcoef(static_cast<std::size_t>(m), 0);  // its pivot's coefficient, reduced
        const std::size_t npmax = static_cast<std::size_t>(std::min(ncols, nrows));  // pairs: distinct pivots
        pair_c.reserve(npmax);
        pair_r.reserve(npmax);
        zero.reserve(static_cast<std::size_t>(ncols));
        vstart.assign(static_cast<std::size_t>(m), -1);
        vlen.assign(static_cast<std::size_t>(m), 0);
        ColumnHeap<double, std::int64_t, std::int64_t> heap;
        std::vector<std::int64_t> wk, wc, at, sums;  // V of the working column as (column, coefficient)
        const bool reduced = keep == KEEP_REDUCED;
        for (std::int64_t pos = 0; pos < ncols; ++pos) {
            const std::int64_t c = columns[pos];
            if (cleared[c]) continue;
            std::int64_t piv = pivot[c];
            if (piv == -1) {  // an empty column
                zero.push_back(c);
                continue;
            }
            if (owner[piv] == -1) {  // pivot still free: already reduced (apparent/emergent pair)
                owner[piv] = static_cast<std::int32_t>(c);
                pcoef[c] = floor_mod(pivot_coef[c], p);
                pair_c.push_back(c);
                pair_r.push_back(piv);
                continue;
            }
            // ---- lazy reduction: a heap of (row value, row, coefficient); V as a list of (column, coefficient)
            wk.assign(1, c);
            wc.assign(1, 1);
            heap.clear();
            heap.reserve(indptr[c + 1] - indptr[c]);
            for (std::int64_t e = indptr[c]; e < indptr[c + 1]; ++e) {
                const std::int64_t r = row_at(e);
                heap.push(row_value[r], r, floor_mod(static_cast<std::int64_t>(coefs[e]), p));
            }
            std::int64_t pc = 0;
            for (;;) {
                // pop the pivot: the least row whose coefficients do not cancel
                const auto top = heap.pop_pivot(p);
                piv = top.key;
                pc = top.coef;
                if (pc == 0) {
                    piv = -1;
                    break;
                }
                const std::int64_t o = owner[piv];
                if (o == -1) break;
                // add factor · (reduced column of o); its pivot entry cancels the popped one: never pushed
                ++additions;
                const std::int64_t factor = (p - pc * mod_inverse(pcoef[o], p) % p) % p;
                if (reduced && vstart[o] != -1) {
                    const std::int64_t a = vstart[o] + 1, b = vstart[o] + vlen[o];
                    heap.reserve(heap.size + (b - a));
                    for (std::int64_t e = a; e < b; ++e) {
                        const std::int64_t r = pool_k[e];
                        heap.push(row_value[r], r, factor * pool_c[e] % p);
                    }
                    continue;
                }
                const std::int64_t ol = vstart[o] == -1 ? 1 : vlen[o];
                for (std::int64_t q = 0; q < ol; ++q) {  // factor · Σ_k V_o[k] · column k
                    std::int64_t k_s = o, k_c = 1;
                    if (vstart[o] != -1) {
                        k_s = pool_k[vstart[o] + q];
                        k_c = pool_c[vstart[o] + q];
                    }
                    const std::int64_t f = factor * k_c % p;
                    wk.push_back(k_s);
                    wc.push_back(f);
                    const std::int64_t a = indptr[k_s], b = indptr[k_s + 1];
                    heap.reserve(heap.size + (b - a));
                    for (std::int64_t e = a; e < b; ++e) {
                        const std::int64_t r = row_at(e);
                        if (r != piv) heap.push(row_value[r], r, f * floor_mod(static_cast<std::int64_t>(coefs[e]), p) % p);
                    }
                }
            }
            if (piv == -1) {
                zero.push_back(c);
                if (keep != KEEP_V_ALL) continue;
            }
            vstart[c] = static_cast<std::int64_t>(pool_k.size());
            if (reduced) {  // the reduced column: its pivot, then the rest of the heap
                pool_k.push_back(piv);
                pool_c.push_back(pc);
                for (;;) {
                    const auto rest = heap.pop_pivot(p);
                    if (rest.coef == 0) break;
                    pool_k.push_back(rest.key);
                    pool_c.push_back(rest.coef);
                }
            } else {  // V_c, duplicates merged and zeros dropped
                merge_entries(wk.data(), wc.data(), static_cast<std::int64_t>(wk.size()), p, at, sums);
                for (std::size_t q = 0; q < at.size(); ++q) {
                    pool_k.push_back(wk[at[q]]);
                    pool_c.push_back(sums[q]);
                }
            }
            vlen[c] = static_cast<std::int64_t>(pool_k.size()) - vstart[c];
            if (piv == -1) continue;
            owner[piv] = static_cast<std::int32_t>(c);
            pcoef[c] = pc;
            pair_c.push_back(c);
            pair_r.push_back(piv);
        }
    }
    return {to_numpy(std::move(pair_c)), to_numpy(std::move(pair_r)), to_numpy(std::move(zero)), additions,
            to_numpy(std::move(vstart)), to_numpy(std::move(vlen)), to_numpy(std::move(pool_k)),
            to_numpy(std::move(pool_c))};
}

// Bind reduce_columns for one pair of (row, coefficient) dtypes; the Python face picks the overload.
// Thesis: Algorithm 2 (ComputeIntervals), §2.3.5.
template <class R, class C>
void bind_reduce_columns(nb::module_& m) {
    m.def("reduce_columns", &reduce_columns<R, C>, nb::arg("indptr"), nb::arg("rows"), nb::arg("coefs"),
          nb::arg("row_value"), nb::arg("state"), nb::arg("p"), nb::arg("keep"));
}

}  // namespace thesis

NB_MODULE(reduction, m) {
    m.doc() = "The stored-matrix column reduction mod p with clearing (thesis Algorithms 1-2, §2.3.5).";
    m.attr("KEEP_V") = thesis::KEEP_V;
    m.attr("KEEP_V_ALL") = thesis::KEEP_V_ALL;
    m.attr("KEEP_REDUCED") = thesis::KEEP_REDUCED;
    namespace nb = nanobind;
    using thesis::In;
    nb::class_<thesis::ColumnState>(m, "ColumnState",
                                    "The columns to reduce, in order, and every column's cleared flag, pivot and "
                                    "pivot coefficient.")
        .def(nb::init<In<std::int64_t, nb::ndim<1>>, In<bool, nb::ndim<1>>, In<std::int64_t, nb::ndim<1>>,
                      In<std::int64_t, nb::ndim<1>>>(),
             nb::arg("columns"), nb::arg("cleared"), nb::arg("pivot"), nb::arg("pivot_coef"));
    // rows as int32 (the explicit engine's coboundaries) or int64, coefficients as int8 (signs) or int64
    thesis::bind_reduce_columns<std::int32_t, std::int8_t>(m);
    thesis::bind_reduce_columns<std::int32_t, std::int64_t>(m);
    thesis::bind_reduce_columns<std::int64_t, std::int8_t>(m);
    thesis::bind_reduce_columns<std::int64_t, std::int64_t>(m);
}
