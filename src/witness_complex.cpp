// Witness complexes W(X, L, ε) (thesis §2.1.2, "The Witness Complex") and JavaPlex's lazy variant.
//
// Both start from the matrix D[l, x] = |l − x| − m(x) (landmark l, point x).  An edge's value is
// min_x max(D[a, x], D[b, x]) (with a witness realising it); a simplex's value in the (strong) witness
// complex is min_x max_{l in σ} D[l, x], computed level by level from the parents.  Port of the numba
// kernels of complexes/witness.py, operation by operation; the parallel loop over parents runs on
// std::thread, each parent writing its own rows, so the output does not depend on the threads.
#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <system_error>
#include <tuple>

#include "arrays.hpp"

namespace thesis {

namespace {

constexpr double kBig = 1e300;  // stands for "not a witness"

// The first position in arr[lo:hi] whose entry is not below x (arr sorted there).
// Thesis: §2.1.2 (witnesses of a simplex are looked up in a landmark's sorted distances).
inline std::int64_t lower_bound_in(const double* arr, std::int64_t lo, std::int64_t hi, double x) {
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

// min_x max(cur[x], row[x]) over all points.  Thesis: §2.1.2 (the witness rule, min over x ∈ X).
inline double minmax_full(const double* cur, const double* row, std::int64_t n_x) {
    double best = kBig;
    for (std::int64_t x = 0; x < n_x; ++x) {
        const double v = cur[x] > row[x] ? cur[x] : row[x];
        best = v < best ? v : best;
    }
    return best;
}

// min_j max(cur[j], row[idx[j]]) over the parent's witnesses only.  Thesis: §2.1.2.
inline double minmax_gather(const double* cur, const std::int64_t* idx, std::int64_t cnt, const double* row) {
    double best = kBig;
    for (std::int64_t j = 0; j < cnt; ++j) {
        double v = row[idx[j]];
        if (cur[j] > v) v = cur[j];
        if (v < best) best = v;
    }
    return best;
}

struct Level {
    const std::int64_t* parents;
    std::int64_t width;
    const double* D;
    std::int64_t n_l, n_x;
    const double* ev;
    const std::int64_t* arg;
    double eps;
    const std::int64_t* order;
    const double* sorted_d;
    std::int64_t sorted_cols;
    bool use_sorted;
};

// Per parent: the landmarks w > last vertex whose edges to every vertex have value <= eps.
// Thesis: §2.1.2 (a simplex is in W only if all its faces are).
std::int64_t candidate_count(const Level& L, std::int64_t r) {
    const std::int64_t* row = L.parents + r * L.width;
    std::int64_t c = 0;
    for (std::int64_t w = row[L.width - 1] + 1; w < L.n_l; ++w) {
        bool ok = true;
        for (std::int64_t i = 0; i < L.width; ++i) {
            if (L.ev[row[i] * L.n_l + w] > L.eps) {
                ok = false;
                break;
            }
        }
        if (ok) ++c;
    }
    return c;
}

// One thread's scratch for witness_parent, n_x entries each: the parent's value at every point (cur)
// and, gathered, the values at the points within eps (ccur) and those points (idx).
struct ParentScratch {
    std::vector<double> cur, ccur;
    std::vector<std::int64_t> idx;
    explicit ParentScratch(std::int64_t n_x)
        : cur(static_cast<std::size_t>(n_x)), ccur(static_cast<std::size_t>(n_x)), idx(static_cast<std::size_t>(n_x)) {}
};

// Children of parent r written into rows start, start + 1, ... (one per candidate).
// Thesis: §2.1.2, the strong witness rule max_i |l_i − x| <= ε + m(x) for some x.
void witness_parent(const Level& L, std::int64_t r, std::int64_t* out, double* out_v, std::uint8_t* valid,
                    std::int64_t start, ParentScratch& scratch) {
    double* cur = scratch.cur.data();
    double* ccur = scratch.ccur.data();
    std::int64_t* idx = scratch.idx.data();
    const std::int64_t width = L.width;
    const std::int64_t n_l = L.n_l, n_x = L.n_x;
    const std::int64_t* row = L.parents + r * width;
    const double* D = L.D;
    const double eps = L.eps;
    std::int64_t cnt = 0;
    double pv = kBig;
    std::int64_t xp = 0;
    for (std::int64_t x = 0; x < n_x; ++x) {
        double mx = D[row[0] * n_x + x];
        for (std::int64_t i = 1; i < width; ++i) {
            const double v = D[row[i] * n_x + x];
            if (v > mx) mx = v;
        }
        if (mx <= eps) {
            cur[x] = mx;
            ccur[cnt] = mx;
            idx[cnt] = x;
            ++cnt;
            if (mx < pv) {
                pv = mx;
                xp = x;
            }
        } else {
            cur[x] = kBig;
        }
    }
    std::int64_t slot = start;
    const std::int64_t last = row[width - 1];
    const bool compressed = 4 * cnt < n_x;
    for (std::int64_t w = last + 1; w < n_l; ++w) {
        double lb = pv;
        bool ok = true;
        for (std::int64_t i = 0; i < width; ++i) {
            const double e = L.ev[row[i] * n_l + w];
            if (e > eps) {
                ok = false;
                break;
            }
            if (e > lb) lb = e;
        }
        if (!ok) continue;
        const double* Dw = D + w * n_x;
        // (the parent is in the complex, so cnt > 0 and xp is a real witness)
        double ub = Dw[xp] > cur[xp] ? Dw[xp] : cur[xp];  // Python's max(cur[xp], D[w, xp])
        for (std::int64_t i = 0; i < width; ++i) {
            const std::int64_t x = L.arg[row[i] * n_l + w];
            const double v = Dw[x] > cur[x] ? Dw[x] : cur[x];
            if (v < ub) ub = v;
        }
        std::int64_t n_scan = n_x + 1;
        std::int64_t u_best = 0;
        if (L.use_sorted && ub > lb) {
            for (std::int64_t i = 0; i < width + 1; ++i) {
                const std::int64_t u = i < width ? row[i] : w;
                const std::int64_t c = lower_bound_in(L.sorted_d + u * L.sorted_cols, 0, L.sorted_cols, ub);
                if (c < n_scan) {
                    n_scan = c;
                    u_best = u;
                }
            }
        }
        double best;
        if (ub <= lb) {
            best = ub;
        } else if (3 * n_scan < (compressed ? cnt : n_x)) {
            best = ub;
            const double* sd = L.sorted_d + u_best * L.sorted_cols;
            const std::int64_t* od = L.order + u_best * L.sorted_cols;
            for (std::int64_t k = 0; k < n_scan; ++k) {
                if (sd[k] >= best) break;
                const std::int64_t x = od[k];
                double v = cur[x];
                if (Dw[x] > v) v = Dw[x];
                if (v < best) best = v;
            }
        } else if (compressed) {
            best = minmax_gather(ccur, idx, cnt, Dw);
        } else {
            best = minmax_full(cur, Dw, n_x);
        }
        std::int64_t* o = out + slot * (width + 1);
        for (std::int64_t i = 0; i < width; ++i) o[i] = row[i];
        o[width] = w;
        out_v[slot] = 0.0 > best ? 0.0 : best;  // Python's max(best, 0.0)
        valid[slot] = best <= eps;
        ++slot;
    }
}

// Refuse an index array with an entry outside [0, bound) before any of it is used.
// Thesis: §2.1.2 (vertices are landmarks 0..L-1, witnesses points 0..N-1).
void check_index_array(const std::int64_t* a, std::size_t size, std::int64_t bound, const char* what) {
    for (std::size_t k = 0; k < size; ++k)
        if (a[k] < 0 || a[k] >= bound) throw std::invalid_argument(std::string("witness_level: ") + what);
}

}  // namespace

// Unclamped edge values min_x max(D[a, x], D[b, x]) and a witness realising each (diagonal: the
// nearest point of each landmark).  Thesis: §2.1.2 (the witness rule for edges, used by both complexes).
std::tuple<Array<double>, Array<std::int64_t>> edge_values(In<double, nb::ndim<2>> D) {
    const std::int64_t n_l = static_cast<std::int64_t>(D.shape(0));
    const std::int64_t n_x = static_cast<std::int64_t>(D.shape(1));
    const double* d = D.data();
    std::vector<double> out(static_cast<std::size_t>(n_l * n_l), 0.0);
    std::vector<std::int64_t> arg(static_cast<std::size_t>(n_l * n_l), 0);
    {
        nb::gil_scoped_release release;
        const double inf = std::numeric_limits<double>::infinity();
        for (std::int64_t a = 0; a < n_l; ++a) {
            const double* Da = d + a * n_x;
            double best0 = inf;
            for (std::int64_t x = 0; x < n_x; ++x) {
                if (Da[x] < best0) {
                    best0 = Da[x];
                    arg[a * n_l + a] = x;
                }
            }
            out[a * n_l + a] = best0;
            // four b at a time: D[a] is read once for them, and each b keeps its own scan in x order
            // (val < best replaces), so the result is the one of one b at a time
            std::int64_t b = a + 1;
            for (; b + 4 <= n_l; b += 4) {
                const double* D0 = d + b * n_x;
                const double* D1 = D0 + n_x;
                const double* D2 = D1 + n_x;
                const double* D3 = D2 + n_x;
                double best0 = inf, best1 = inf, best2 = inf, best3 = inf;
                std::int64_t bx0 = 0, bx1 = 0, bx2 = 0, bx3 = 0;
                for (std::int64_t x = 0; x < n_x; ++x) {
                    const double u = Da[x];
                    const double v0 = u > D0[x] ? u : D0[x];
                    const double v1 = u > D1[x] ? u : D1[x];
                    const double v2 = u > D2[x] ? u : D2[x];
                    const double v3 = u > D3[x] ? u : D3[x];
                    if (v0 < best0) { best0 = v0; bx0 = x; }
                    if (v1 < best1) { best1 = v1; bx1 = x; }
                    if (v2 < best2) { best2 = v2; bx2 = x; }
                    if (v3 < best3) { best3 = v3; bx3 = x; }
                }
                const double best[4] = {best0, best1, best2, best3};
                const std::int64_t bx[4] = {bx0, bx1, bx2, bx3};
                for (int j = 0; j < 4; ++j) {
                    out[a * n_l + b + j] = best[j];
                    out[(b + j) * n_l + a] = best[j];
                    arg[a * n_l + b + j] = bx[j];
                    arg[(b + j) * n_l + a] = bx[j];
                }
            }
            for (; b < n_l; ++b) {
                const double* Db = d + b * n_x;
                double best = inf;
                std::int64_t bx = 0;
                for (std::int64_t x = 0; x < n_x; ++x) {
                    const double u = Da[x];
                    const double v = Db[x];
                    const double val = u > v ? u : v;
                    if (val < best) {
                        best = val;
                        bx = x;
                    }
                }
                out[a * n_l + b] = best;
                out[b * n_l + a] = best;
                arg[a * n_l + b] = bx;
                arg[b * n_l + a] = bx;
            }
        }
    }
    const std::size_t s = static_cast<std::size_t>(n_l);
    return {to_numpy(std::move(out), {s, s}), to_numpy(std::move(arg), {s, s})};
}

// Each landmark's points by increasing distance, order[l] and their distances sorted_d[l], used when
// use_sorted (else placeholders).
struct SortedDistances {
    In<std::int64_t, nb::ndim<2>> order;
    In<double, nb::ndim<2>> sorted_d;
    bool use_sorted;
};

// Children one dimension up with value min_x max_{l in child} D[l, x] (<= eps), lexicographic.
// ev[a, b] is the (unclamped) value of edge ab and arg[a, b] a witness realising it; they give a
// lower bound and candidate witnesses.  With use_sorted, order[l] lists the points by increasing
// D[l, x] (sorted_d[l]): only the prefix of the shortest such list below the current best is scanned.
// Parents are processed on thread_count(n_threads) threads, each writing its candidates into its own
// rows.  Thesis: §2.1.2 "The Witness Complex" (a p-simplex is in W when its faces are and a witness sees it).
std::tuple<Array<std::int64_t>, Array<double>> witness_level(
    In<std::int64_t, nb::ndim<2>> parents, In<double, nb::ndim<2>> D, In<double, nb::ndim<2>> ev,
    In<std::int64_t, nb::ndim<2>> arg, double eps, const SortedDistances& sorted, int n_threads) {
    const In<std::int64_t, nb::ndim<2>>& order = sorted.order;
    const In<double, nb::ndim<2>>& sorted_d = sorted.sorted_d;
    const bool use_sorted = sorted.use_sorted;
    Level L;
    L.parents = parents.data();
    L.width = static_cast<std::int64_t>(parents.shape(1));
    L.D = D.data();
    L.n_l = static_cast<std::int64_t>(D.shape(0));
    L.n_x = static_cast<std::int64_t>(D.shape(1));
    L.ev = ev.data();
    L.arg = arg.data();
    L.eps = eps;
    L.order = order.data();
    L.sorted_d = sorted_d.data();
    L.sorted_cols = static_cast<std::int64_t>(sorted_d.shape(1));
    L.use_sorted = use_sorted;
    const std::int64_t m = static_cast<std::int64_t>(parents.shape(0));
    const std::int64_t width = L.width;
    const std::size_t nl = static_cast<std::size_t>(L.n_l);
    if (width < 1) throw std::invalid_argument("witness_level: parents must have at least one column");
    if (L.n_x < 1) throw std::invalid_argument("witness_level: D has no points (columns)");
    if (ev.shape(0) != nl || ev.shape(1) != nl || arg.shape(0) != nl || arg.shape(1) != nl)
        throw std::invalid_argument("witness_level: ev and arg must be L x L for L landmarks (rows of D)");
    check_index_array(L.parents, parents.size(), L.n_l, "a parent vertex is out of range");
    check_index_array(L.arg, arg.size(), L.n_x, "a witness in arg is out of range");
    if (use_sorted) {
        if (order.shape(0) != nl || sorted_d.shape(0) != nl || order.shape(1) != D.shape(1) ||
            sorted_d.shape(1) != D.shape(1))
            throw std::invalid_argument("witness_level: order and sorted_d must have the shape of D");
        check_index_array(L.order, order.size(), L.n_x, "a point in order is out of range");
    }

    std::vector<std::int64_t> counts(static_cast<std::size_t>(m));
    std::vector<std::int64_t> starts(static_cast<std::size_t>(m) + 1, 0);
    std::vector<std::int64_t> out;
    std::vector<double> out_v;
    std::vector<std::uint8_t> valid;
    {
        nb::gil_scoped_release release;
        for (std::int64_t r = 0; r < m; ++r) counts[r] = candidate_count(L, r);
        for (std::int64_t r = 0; r < m; ++r) starts[r + 1] = starts[r] + counts[r];
        const std::int64_t total = starts[m];
        out.resize(static_cast<std::size_t>(total * (width + 1)));
        out_v.resize(static_cast<std::size_t>(total));
        valid.assign(static_cast<std::size_t>(total), 0);
        const int threads = static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(m, thread_count(n_threads))));
        const std::int64_t n_chunks = std::max<std::int64_t>(1, std::min<std::int64_t>(m, 64 * std::int64_t(threads)));
        std::atomic<std::int64_t> next{0};
        auto work = [&]() {
            ParentScratch scratch(L.n_x);
            for (std::int64_t c = next.fetch_add(1); c < n_chunks; c = next.fetch_add(1)) {
                for (std::int64_t r = c * m / n_chunks; r < (c + 1) * m / n_chunks; ++r) {
                    if (counts[r] > 0)
                        witness_parent(L, r, out.data(), out_v.data(), valid.data(), starts[r], scratch);
                }
            }
        };
        if (threads == 1) {
            work();
        } else {
            std::vector<std::thread> pool;
            pool.reserve(static_cast<std::size_t>(threads - 1));
            for (int t = 1; t < threads; ++t) {
                try {
                    pool.emplace_back(work);
                } catch (const std::system_error&) {
                    break;  // no more threads to be had: those started and this one share the chunks
                }
            }
            work();
            for (auto& th : pool) th.join();
        }
        // keep the valid rows, in order
        std::size_t kept = 0;
        for (std::int64_t s = 0; s < total; ++s) {
            if (!valid[s]) continue;
            if (kept != static_cast<std::size_t>(s)) {
                for (std::int64_t i = 0; i <= width; ++i) out[kept * (width + 1) + i] = out[s * (width + 1) + i];
                out_v[kept] = out_v[s];
            }
            ++kept;
        }
        out.resize(kept * static_cast<std::size_t>(width + 1));
        out_v.resize(kept);
    }
    const std::size_t kept = out_v.size();
    return {to_numpy(std::move(out), {kept, static_cast<std::size_t>(width + 1)}), to_numpy(std::move(out_v))};
}

}  // namespace thesis

NB_MODULE(witness_complex, m) {
    namespace nb = nanobind;
    m.doc() = "Witness and lazy witness complexes (thesis §2.1.2, \"The Witness Complex\").";
    m.def("edge_values", &thesis::edge_values, nb::arg("D"),
          "Unclamped edge values min_x max(D[a, x], D[b, x]) and a witness realising each.");
    nb::class_<thesis::SortedDistances>(m, "SortedDistances",
                                        "Each landmark's points by increasing distance and those distances, used "
                                        "when use_sorted.")
        .def(nb::init<thesis::In<std::int64_t, nb::ndim<2>>, thesis::In<double, nb::ndim<2>>, bool>(),
             nb::arg("order"), nb::arg("sorted_d"), nb::arg("use_sorted"));
    m.def("witness_level", &thesis::witness_level, nb::arg("parents"), nb::arg("D"), nb::arg("ev"), nb::arg("arg"),
          nb::arg("eps"), nb::arg("sorted"), nb::arg("n_threads") = 0,
          "Children one dimension up with value min_x max_{l in child} D[l, x] (<= eps), lexicographic.");
}
