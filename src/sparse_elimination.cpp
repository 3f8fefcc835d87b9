// Integer homology by elimination: sparse Gaussian elimination on unit pivots with the Markowitz rule,
// over Z (pivots ±1, every entry kept within a limit) or over Z/p, and the dense unit-pivot elimination
// that finishes it.  The first stage of thesis_lib.homology.smith (driven by thesis_lib/homology/_elimination.py).
//
// Each step is unimodular over Z, A ~ (v) ⊕ A' with A' the Schur complement, so after t pivots
// SNF(A) = I_t ⊕ SNF(core); over Z/p the core is empty and t is the rank.
#include "arrays.hpp"
#include "column_heap.hpp"

#include <nanobind/stl/tuple.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <tuple>

namespace thesis {

namespace {

constexpr int kShift = 32;
constexpr std::int64_t kLow = (std::int64_t(1) << kShift) - 1;
// Entries over Z are kept within lim <= 2^31: |a - f b| <= 2^31 + 2^62 < 2^63 (no int64 overflow).
constexpr std::int64_t kMaxLimit = std::int64_t(1) << 31;
// Moduli below 2^31: a product of two residues fits in int64.
constexpr std::int64_t kMaxModulus = (std::int64_t(1) << 31) - 1;
// Row and column indices and counts share one int64 heap key, count << 32 | index.
constexpr std::int64_t kMaxLines = (std::int64_t(1) << 31) - 1;

// A new NumPy bool array holding the flags (0/1 bytes).
Array<bool> bool_array(const std::vector<std::uint8_t>& flags) {
    const std::size_t n = flags.size();
    std::unique_ptr<bool[]> data(new bool[n ? n : 1]);
    for (std::size_t i = 0; i < n; ++i) data[i] = flags[i] != 0;
    bool* raw = data.release();
    nb::capsule owner(raw, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    std::size_t shape[1] = {n};
    return Array<bool>(raw, 1, shape, owner);
}

// The binary min-heap of int64 keys (count << 32 | line) giving the shortest rows or columns; stale
// keys are dropped lazily when they reach the top.
// Thesis: §2.2.1 (choosing the pivots of the elementary operations that reduce M_p).
struct KeyHeap {
    std::vector<std::int64_t> heap;
    std::int64_t size = 0;

    void push(std::int64_t key) {
        if (static_cast<std::size_t>(size) == heap.size()) heap.resize(heap.empty() ? 16 : 2 * heap.size());
        std::int64_t i = size;
        heap[i] = key;
        while (i > 0) {
            const std::int64_t parent = (i - 1) >> 1;
            if (heap[parent] <= heap[i]) break;
            std::swap(heap[parent], heap[i]);
            i = parent;
        }
        ++size;
    }

    std::int64_t pop() {
        const std::int64_t top = heap[0];
        --size;
        heap[0] = heap[size];
        std::int64_t i = 0;
        for (;;) {
            const std::int64_t left = 2 * i + 1;
            if (left >= size) break;
            std::int64_t child = left;
            if (left + 1 < size && heap[left + 1] < heap[left]) child = left + 1;
            if (heap[i] <= heap[child]) break;
            std::swap(heap[i], heap[child]);
            i = child;
        }
        return top;
    }

    std::int64_t top() const { return heap[0]; }

    // Pop stale keys (line dead or blocked, count changed or 0) until a live key is on top.
    void drop_stale(const std::vector<std::uint8_t>& dead, const std::vector<std::uint8_t>& blocked,
                    const std::vector<std::int64_t>& count) {
        while (size > 0) {
            const std::int64_t key = heap[0];
            const std::int64_t line = key & kLow;
            if (dead[line] || blocked[line] || count[line] != (key >> kShift) || count[line] == 0)
                pop();
            else
                break;
        }
    }
};

// Offset of col in the sorted run pool_c[start, start + length), or -1.
inline std::int64_t locate(const std::vector<std::int64_t>& pool_c, std::int64_t start, std::int64_t length,
                           std::int64_t col) {
    std::int64_t lo = start, hi = start + length;
    while (lo < hi) {
        const std::int64_t mid = (lo + hi) >> 1;
        if (pool_c[mid] < col)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < start + length && pool_c[lo] == col) return lo - start;
    return -1;
}

// A pivot candidate: a unit of Z (±1) or any nonzero residue of Z/p.
inline bool eligible(std::int64_t v, std::int64_t p) { return p != 0 ? v != 0 : (v == 1 || v == -1); }

// v is a unit of Z (p = 0) or of Z/p for any modulus p (v reduced to [0, p)): gcd(v, p) = 1.
inline bool is_unit(std::int64_t v, std::int64_t p) {
    if (p == 0) return v == 1 || v == -1;
    std::int64_t a = v, b = p;
    while (b != 0) {
        const std::int64_t t = a % b;
        a = b;
        b = t;
    }
    return a == 1;
}

// Rewrite the live rows contiguously into new pools of room 2·live + extra (at least 16).
void compact_rows(std::vector<std::int64_t>& pool_c, std::vector<std::int64_t>& pool_v, std::vector<std::int64_t>& rs,
                  const std::vector<std::int64_t>& rl, const std::vector<std::uint8_t>& dead, std::int64_t extra,
                  std::int64_t& top) {
    const std::size_t n = rs.size();
    std::int64_t live = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!dead[i]) live += rl[i];
    const std::int64_t cap = std::max<std::int64_t>(16, 2 * live + extra);
    std::vector<std::int64_t> nc(static_cast<std::size_t>(cap)), nv(static_cast<std::size_t>(cap));
    std::int64_t t0 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (dead[i] || rl[i] == 0) {
            rs[i] = t0;
            continue;
        }
        const std::int64_t s = rs[i];
        for (std::int64_t t = 0; t < rl[i]; ++t) {
            nc[t0 + t] = pool_c[s + t];
            nv[t0 + t] = pool_v[s + t];
        }
        rs[i] = t0;
        t0 += rl[i];
    }
    pool_c.swap(nc);
    pool_v.swap(nv);
    top = t0;
}

template <class T>
inline void ensure(std::vector<T>& v, std::int64_t need) {
    if (static_cast<std::size_t>(need) <= v.size()) return;
    std::size_t cap = std::max<std::size_t>(16, 2 * v.size());
    while (cap < static_cast<std::size_t>(need)) cap *= 2;
    v.resize(cap);
}

}  // namespace

// The options of markowitz: the modulus p (0: Z), the bound lim on entries over Z, how many shortest
// rows and columns a pivot is searched among, and the density (with at most max_dense entries) at
// which the active matrix is handed to the dense kernel.
struct Options {
    std::int64_t p;
    std::int64_t lim;
    std::int64_t search;
    double density;
    std::int64_t max_dense;
};

// Sparse Markowitz elimination of a CSC matrix on unit pivots: while the active matrix is sparse,
// pivot on the unit entry of least (r - 1)(c - 1) among the `search` shortest rows and columns and
// replace the other rows of its column by the Schur complement; over Z a step that would make an
// entry exceed lim sets its column aside.  Returns (rank, pivot-row mask, core rows, core CSR
// pointers, core columns, core values) — the core being the live rows when no pivot is left or the
// active matrix is dense enough (density, max_dense) for the dense kernel.
// Thesis: Theorem 2.20 and §2.2.1 (Smith normal form of M_p by elementary operations; k_p = rank).
std::tuple<std::int64_t, Array<bool>, Array<std::int64_t>, Array<std::int64_t>, Array<std::int64_t>,
           Array<std::int64_t>>
markowitz(In<std::int64_t, nb::ndim<1>> indptr_a, In<std::int64_t, nb::ndim<1>> indices_a,
          In<std::int64_t, nb::ndim<1>> data_a, std::int64_t n_rows, In<bool, nb::ndim<1>> skip_a,
          const Options& options) {
    const std::int64_t p = options.p, lim = options.lim, search = options.search, max_dense = options.max_dense;
    const double density = options.density;
    // ---- checks (the Python layer validates; these keep every index and product in range)
    const std::int64_t n_ptr = static_cast<std::int64_t>(indptr_a.shape(0));
    if (n_ptr < 1) throw std::invalid_argument("indptr must have at least one entry");
    const std::int64_t n_cols = n_ptr - 1;
    const std::int64_t n_nz = static_cast<std::int64_t>(indices_a.shape(0));
    if (static_cast<std::int64_t>(data_a.shape(0)) != n_nz)
        throw std::invalid_argument("indices and data must have the same length");
    if (static_cast<std::int64_t>(skip_a.shape(0)) != n_cols)
        throw std::invalid_argument("skip must have one entry per column");
    if (n_rows < 0 || n_rows > kMaxLines || n_cols > kMaxLines)
        throw std::invalid_argument("the matrix must have at most 2^31 - 1 rows and columns");
    if (p != 0 && (p < 2 || p > kMaxModulus)) throw std::invalid_argument("p must be 0 or a prime below 2^31");
    if (p == 0 && (lim < 0 || lim > kMaxLimit)) throw std::invalid_argument("lim must lie in [0, 2^31]");
    if (search < 0) throw std::invalid_argument("search must be non-negative");
    if (!(density >= 0.0) || !std::isfinite(density)) throw std::invalid_argument("density must be finite and >= 0");
    const std::int64_t* indptr = indptr_a.data();
    const std::int64_t* indices = indices_a.data();
    const std::int64_t* data = data_a.data();
    const bool* skip = skip_a.data();
    if (indptr[0] < 0 || indptr[n_cols] > n_nz) throw std::invalid_argument("indptr out of range of indices");
    for (std::int64_t j = 0; j < n_cols; ++j) {
        if (indptr[j + 1] < indptr[j]) throw std::invalid_argument("indptr must be non-decreasing");
        for (std::int64_t t = indptr[j]; t < indptr[j + 1]; ++t) {
            if (indices[t] < 0 || indices[t] >= n_rows) throw std::invalid_argument("row index out of range");
            if (t > indptr[j] && indices[t] <= indices[t - 1])
                throw std::invalid_argument("row indices must be sorted within each column, without duplicates");
            if (p == 0 && !skip[j] && (data[t] > lim || data[t] < -lim))
                throw std::invalid_argument("entries over Z must satisfy |entry| <= lim");
        }
    }

    std::int64_t rank = 0;
    std::vector<std::uint8_t> pivot_rows(static_cast<std::size_t>(n_rows), 0);
    std::vector<std::int64_t> core_rows, core_ptr, core_cols, core_vals;
    {
        nb::gil_scoped_release release;
        const std::size_t NR = static_cast<std::size_t>(n_rows), NC = static_cast<std::size_t>(n_cols);
        // ---- rows from the CSC input (values reduced mod p; zeros dropped)
        std::vector<std::int64_t> rl(NR, 0);
        for (std::int64_t j = 0; j < n_cols; ++j) {
            if (skip[j]) continue;
            for (std::int64_t t = indptr[j]; t < indptr[j + 1]; ++t) {
                const std::int64_t v = p != 0 ? floor_mod(data[t], p) : data[t];
                if (v != 0) rl[indices[t]] += 1;
            }
        }
        std::vector<std::int64_t> rs(NR, 0);
        std::int64_t acc = 0;
        for (std::size_t i = 0; i < NR; ++i) {
            rs[i] = acc;
            acc += rl[i];
        }
        std::vector<std::int64_t> pool_c(static_cast<std::size_t>(std::max<std::int64_t>(16, 3 * acc)));
        std::vector<std::int64_t> pool_v(pool_c.size());
        std::vector<std::int64_t> fill(rs);
        // column lists: rows that may hold an entry; exact live counts
        std::vector<std::int64_t> cs(NC, 0), cl(NC, 0), ccap(NC, 0), cnt(NC, 0);
        std::vector<std::int64_t> cpool(static_cast<std::size_t>(std::max<std::int64_t>(16, 2 * acc + 4 * n_cols)));
        std::int64_t ctop = 0;
        for (std::int64_t j = 0; j < n_cols; ++j) {  // CSC columns in column order: each row run stays sorted
            cs[j] = ctop;
            if (skip[j]) continue;
            for (std::int64_t t = indptr[j]; t < indptr[j + 1]; ++t) {
                const std::int64_t v = p != 0 ? floor_mod(data[t], p) : data[t];
                if (v != 0) {
                    const std::int64_t i = indices[t];
                    pool_c[fill[i]] = j;
                    pool_v[fill[i]] = v;
                    fill[i] += 1;
                    cpool[ctop + cl[j]] = i;
                    cl[j] += 1;
                }
            }
            cnt[j] = cl[j];
            ccap[j] = cl[j] + 4;
            ctop += ccap[j];
        }
        std::int64_t top = acc;
        std::vector<std::uint8_t> row_dead(NR, 0), col_dead(NC, 0), row_blocked(NR, 0), col_blocked(NC, 0);
        // ---- heaps of (count, index)
        KeyHeap cheap, rheap;
        cheap.heap.resize(NC + 16);
        rheap.heap.resize(NR + 16);
        for (std::int64_t j = 0; j < n_cols; ++j)
            if (cnt[j] > 0) cheap.push((cnt[j] << kShift) | j);
        for (std::int64_t i = 0; i < n_rows; ++i)
            if (rl[i] > 0) rheap.push((rl[i] << kShift) | i);
        // ---- work buffers
        std::vector<std::int64_t> stash(64);
        std::vector<std::int64_t> kbuf(64), fbuf(64), new_start(64), new_len(64);
        std::vector<std::int64_t> fill_k(256), fill_j(256), cancel_j(256);
        std::int64_t live_r = 0, live_c = 0;
        for (std::size_t i = 0; i < NR; ++i)
            if (rl[i] > 0) ++live_r;
        for (std::size_t j = 0; j < NC; ++j)
            if (cnt[j] > 0) ++live_c;
        std::int64_t nnz = acc;
        std::vector<std::int64_t> seen(NR, 0);  // stamps: a row cancelled then filled again is listed twice
        std::int64_t stamp = 0;
        for (;;) {
            if (live_r * live_c <= max_dense &&
                static_cast<double>(nnz) >= density * static_cast<double>(live_r) * static_cast<double>(live_c))
                break;  // dense enough: the caller finishes with the dense kernel
            // ---------------- choose a pivot (Markowitz, limited search)
            std::int64_t best = -1, bi = -1, bj = -1, bv = 0;
            std::int64_t n_exam = 0, n_stash = 0;
            while (n_exam < search) {
                cheap.drop_stale(col_dead, col_blocked, cnt);
                rheap.drop_stale(row_dead, row_blocked, rl);
                if (cheap.size == 0 && rheap.size == 0) break;
                const bool use_col =
                    rheap.size == 0 || (cheap.size > 0 && (cheap.top() >> kShift) <= (rheap.top() >> kShift));
                if (use_col) {
                    const std::int64_t key = cheap.pop();
                    const std::int64_t j = key & kLow;
                    const std::int64_t c = cnt[j];
                    bool found = false;
                    std::int64_t w = cs[j];
                    ++stamp;
                    for (std::int64_t t = cs[j]; t < cs[j] + cl[j]; ++t) {  // drop stale and repeated rows
                        const std::int64_t k = cpool[t];
                        if (row_dead[k] || seen[k] == stamp) continue;
                        seen[k] = stamp;
                        const std::int64_t off = locate(pool_c, rs[k], rl[k], j);
                        if (off < 0) continue;
                        cpool[w] = k;
                        ++w;
                        const std::int64_t v = pool_v[rs[k] + off];
                        if (eligible(v, p)) {
                            found = true;
                            const std::int64_t cost = (c - 1) * (rl[k] - 1);
                            if (best < 0 || cost < best) {
                                best = cost;
                                bi = k;
                                bj = j;
                                bv = v;
                            }
                        }
                    }
                    cl[j] = w - cs[j];
                    if (!found) {
                        col_blocked[j] = 1;
                    } else {
                        ensure(stash, n_stash + 1);
                        stash[n_stash] = (key << 1) | 1;
                        ++n_stash;
                        ++n_exam;
                    }
                } else {
                    const std::int64_t key = rheap.pop();
                    const std::int64_t i = key & kLow;
                    const std::int64_t r = rl[i];
                    bool found = false;
                    for (std::int64_t t = rs[i]; t < rs[i] + r; ++t) {
                        const std::int64_t v = pool_v[t];
                        if (eligible(v, p)) {
                            found = true;
                            const std::int64_t cost = (r - 1) * (cnt[pool_c[t]] - 1);
                            if (best < 0 || cost < best) {
                                best = cost;
                                bi = i;
                                bj = pool_c[t];
                                bv = v;
                            }
                        }
                    }
                    if (!found) {
                        row_blocked[i] = 1;
                    } else {
                        ensure(stash, n_stash + 1);
                        stash[n_stash] = key << 1;
                        ++n_stash;
                        ++n_exam;
                    }
                }
                if (best == 0) break;
            }
            for (std::int64_t s = 0; s < n_stash; ++s) {
                const std::int64_t key = stash[s] >> 1;
                if (stash[s] & 1)
                    cheap.push(key);
                else
                    rheap.push(key);
            }
            if (best < 0) break;
            const std::int64_t i = bi, j = bj, v = bv;
            // ---------------- rows to update: the other live rows of column j
            std::int64_t nk = 0, need = 0;
            const std::int64_t vinv = p != 0 ? mod_inverse(v, p) : v;  // over Z, v = ±1 is its own inverse
            ++stamp;
            for (std::int64_t t = cs[j]; t < cs[j] + cl[j]; ++t) {
                const std::int64_t k = cpool[t];
                if (row_dead[k] || k == i || seen[k] == stamp) continue;
                seen[k] = stamp;
                const std::int64_t off = locate(pool_c, rs[k], rl[k], j);
                if (off < 0) continue;
                ensure(kbuf, nk + 1);
                ensure(fbuf, nk + 1);
                kbuf[nk] = k;
                const std::int64_t a = pool_v[rs[k] + off];
                fbuf[nk] = p != 0 ? (a * vinv) % p : a * v;
                ++nk;
                need += rl[k] + rl[i];
            }
            if (top + need > static_cast<std::int64_t>(pool_c.size()))
                compact_rows(pool_c, pool_v, rs, rl, row_dead, need, top);
            ensure(new_start, nk);
            ensure(new_len, nk);
            std::int64_t n_fill = 0, n_cancel = 0;
            bool over = false;
            const std::int64_t top0 = top;
            const std::int64_t si = rs[i], li = rl[i];
            for (std::int64_t q = 0; q < nk; ++q) {
                const std::int64_t k = kbuf[q];
                const std::int64_t f = fbuf[q];
                const std::int64_t sk = rs[k], lk = rl[k];
                ensure(fill_k, n_fill + li);
                ensure(fill_j, n_fill + li);
                ensure(cancel_j, n_cancel + li);
                std::int64_t a_ = 0, b_ = 0, out = top;
                while (a_ < lk || b_ < li) {
                    if (b_ >= li || (a_ < lk && pool_c[sk + a_] < pool_c[si + b_])) {
                        pool_c[out] = pool_c[sk + a_];
                        pool_v[out] = pool_v[sk + a_];
                        ++out;
                        ++a_;
                        continue;
                    }
                    const std::int64_t col = pool_c[si + b_];
                    if (col == j) {  // the pivot column: eliminated by construction
                        ++b_;
                        if (a_ < lk && pool_c[sk + a_] == j) ++a_;
                        continue;
                    }
                    std::int64_t old;
                    bool fresh;
                    if (a_ < lk && pool_c[sk + a_] == col) {
                        old = pool_v[sk + a_];
                        ++a_;
                        fresh = false;
                    } else {
                        old = 0;
                        fresh = true;
                    }
                    ++b_;
                    std::int64_t val;
                    if (p != 0) {
                        val = (old + p - (f * pool_v[si + b_ - 1]) % p) % p;
                    } else {
                        val = old - f * pool_v[si + b_ - 1];  // |old|, |f|, |entry| <= lim <= 2^31
                        if (val > lim || val < -lim) {
                            over = true;
                            break;
                        }
                    }
                    if (val == 0) {
                        if (!fresh) {
                            cancel_j[n_cancel] = col;
                            ++n_cancel;
                        }
                        continue;
                    }
                    if (fresh) {
                        fill_k[n_fill] = k;
                        fill_j[n_fill] = col;
                        ++n_fill;
                    }
                    pool_c[out] = col;
                    pool_v[out] = val;
                    ++out;
                }
                if (over) break;
                new_start[q] = top;
                new_len[q] = out - top;
                top = out;
            }
            if (over) {  // this step would leave int64's safe range: set the column aside
                top = top0;
                // A column already set aside was reached through the row scan of row i; nothing else
                // changes, so the same pivot would be chosen again forever (the numba kernel hung
                // here): set the row aside too.  Rows and columns set aside return when they change.
                if (col_blocked[j]) row_blocked[i] = 1;
                col_blocked[j] = 1;
                continue;
            }
            // ---------------- commit the step
            for (std::int64_t q = 0; q < nk; ++q) {
                const std::int64_t k = kbuf[q];
                nnz += new_len[q] - rl[k];
                if (new_len[q] == 0) --live_r;
                rs[k] = new_start[q];
                rl[k] = new_len[q];
            }
            for (std::int64_t t = 0; t < n_fill; ++t) {
                const std::int64_t jj = fill_j[t];
                if (cl[jj] == ccap[jj]) {  // move the column list to the top of its pool, doubled
                    const std::int64_t cap = 2 * ccap[jj] + 4;
                    ensure(cpool, ctop + cap);
                    for (std::int64_t u = 0; u < cl[jj]; ++u) cpool[ctop + u] = cpool[cs[jj] + u];
                    cs[jj] = ctop;
                    ccap[jj] = cap;
                    ctop += cap;
                }
                cpool[cs[jj] + cl[jj]] = fill_k[t];
                cl[jj] += 1;
                cnt[jj] += 1;
            }
            for (std::int64_t t = 0; t < n_cancel; ++t) cnt[cancel_j[t]] -= 1;
            for (std::int64_t t = si; t < si + li; ++t) {
                const std::int64_t jj = pool_c[t];
                if (jj != j) {
                    cnt[jj] -= 1;
                    if (cnt[jj] == 0) --live_c;
                }
            }
            nnz -= li;
            --live_r;
            --live_c;
            row_dead[i] = 1;
            col_dead[j] = 1;
            pivot_rows[i] = 1;
            ++rank;
            for (std::int64_t t = si; t < si + li; ++t) {
                const std::int64_t jj = pool_c[t];
                if (jj != j && cnt[jj] > 0) {
                    col_blocked[jj] = 0;
                    cheap.push((cnt[jj] << kShift) | jj);
                }
            }
            for (std::int64_t q = 0; q < nk; ++q) {
                const std::int64_t k = kbuf[q];
                row_blocked[k] = 0;
                if (rl[k] > 0) rheap.push((rl[k] << kShift) | k);
            }
        }
        // ---- the core: live rows with entries, as CSR over the original row and column indices
        std::int64_t n_core = 0, core_nnz = 0;
        for (std::size_t r = 0; r < NR; ++r) {
            if (!row_dead[r] && rl[r] > 0) {
                ++n_core;
                core_nnz += rl[r];
            }
        }
        core_rows.resize(static_cast<std::size_t>(n_core));
        core_ptr.assign(static_cast<std::size_t>(n_core + 1), 0);
        core_cols.resize(static_cast<std::size_t>(core_nnz));
        core_vals.resize(static_cast<std::size_t>(core_nnz));
        std::int64_t q = 0, pos = 0;
        for (std::int64_t r = 0; r < n_rows; ++r) {
            if (!row_dead[r] && rl[r] > 0) {
                core_rows[q] = r;
                for (std::int64_t t = 0; t < rl[r]; ++t) {
                    core_cols[pos + t] = pool_c[rs[r] + t];
                    core_vals[pos + t] = pool_v[rs[r] + t];
                }
                pos += rl[r];
                ++q;
                core_ptr[q] = pos;
            }
        }
    }
    return {rank, bool_array(pivot_rows), to_numpy(std::move(core_rows)), to_numpy(std::move(core_ptr)),
            to_numpy(std::move(core_cols)), to_numpy(std::move(core_vals))};
}

// Unit-pivot elimination of a dense int64 matrix in place, column by column: for each column a row
// with a unit entry (over Z the one with the smallest entries) is the pivot and every other live row
// is updated; over Z a step whose update could exceed lim is skipped.  Passes repeat while they make
// progress.  p = 0 for Z, else any modulus below 2^31 with entries in [0, p).  Returns (pivots,
// pivot-row mask, eliminated-column mask).
// Thesis: Theorem 2.20 (elementary row operations with invertible pivots), §2.2.1.
std::tuple<std::int64_t, Array<bool>, Array<bool>> dense_unit_elimination(Out<std::int64_t, nb::ndim<2>> a_arr,
                                                                          std::int64_t p, std::int64_t lim) {
    const std::int64_t n_r = static_cast<std::int64_t>(a_arr.shape(0));
    const std::int64_t n_c = static_cast<std::int64_t>(a_arr.shape(1));
    if (p < 0 || p > kMaxModulus) throw std::invalid_argument("p must be 0 or a modulus below 2^31");
    if (p == 0 && (lim < 0 || lim > kMaxLimit)) throw std::invalid_argument("lim must lie in [0, 2^31]");
    std::int64_t* A = a_arr.data();
    for (std::int64_t e = 0; e < n_r * n_c; ++e) {
        if (p != 0 && (A[e] < 0 || A[e] >= p)) throw std::invalid_argument("entries mod p must lie in [0, p)");
        if (p == 0 && (A[e] > lim || A[e] < -lim)) throw std::invalid_argument("entries over Z must satisfy |entry| <= lim");
    }
    std::vector<std::uint8_t> alive(static_cast<std::size_t>(n_r), 1), done(static_cast<std::size_t>(n_c), 0);
    std::int64_t pivots = 0;
    {
        nb::gil_scoped_release release;
        auto at = [A, n_c](std::int64_t i, std::int64_t c) -> std::int64_t& { return A[i * n_c + c]; };
        std::vector<std::int64_t> rmax(static_cast<std::size_t>(n_r), 0);  // over Z: an upper bound of |a[i, :]|
        if (p == 0) {
            for (std::int64_t i = 0; i < n_r; ++i)
                for (std::int64_t c = 0; c < n_c; ++c) {
                    const std::int64_t x = std::abs(at(i, c));
                    if (x > rmax[i]) rmax[i] = x;
                }
        }
        std::vector<std::int64_t> idx(static_cast<std::size_t>(n_c));
        for (;;) {
            bool progress = false;
            for (std::int64_t j = 0; j < n_c; ++j) {
                if (done[j]) continue;
                std::int64_t k = -1;
                for (std::int64_t i = 0; i < n_r; ++i) {
                    if (alive[i] && is_unit(at(i, j), p)) {
                        if (k < 0 || (p == 0 && rmax[i] < rmax[k])) {
                            k = i;
                            if (p != 0) break;
                        }
                    }
                }
                if (k < 0) continue;
                const std::int64_t v = at(k, j);
                std::int64_t inv;
                if (p == 0) {
                    bool safe = true;  // |a[i, j]| rmax[k] + rmax[i] <= 2^62 + 2^31: no overflow
                    for (std::int64_t i = 0; i < n_r; ++i) {
                        if (alive[i] && i != k && at(i, j) != 0 && std::abs(at(i, j)) * rmax[k] + rmax[i] > lim) {
                            safe = false;
                            break;
                        }
                    }
                    if (!safe) continue;
                    inv = v;
                } else {
                    inv = mod_inverse(v, p);
                }
                std::int64_t nk = 0;
                for (std::int64_t c = 0; c < n_c; ++c) {
                    if (at(k, c) != 0) {
                        idx[nk] = c;
                        ++nk;
                    }
                }
                const std::int64_t* rowk = A + k * n_c;
                for (std::int64_t i = 0; i < n_r; ++i) {
                    if (!alive[i] || i == k || at(i, j) == 0) continue;
                    std::int64_t f = at(i, j) * inv;
                    std::int64_t* rowi = A + i * n_c;
                    if (p != 0) {
                        f = f % p;  // both factors in [0, p)
                        for (std::int64_t t = 0; t < nk; ++t) {
                            const std::int64_t c = idx[t];
                            rowi[c] = floor_mod(rowi[c] - f * rowk[c], p);
                        }
                    } else {
                        std::int64_t top = rmax[i];
                        for (std::int64_t t = 0; t < nk; ++t) {
                            const std::int64_t c = idx[t];
                            const std::int64_t x = rowi[c] - f * rowk[c];
                            rowi[c] = x;
                            if (std::abs(x) > top) top = std::abs(x);
                        }
                        rmax[i] = top;
                    }
                }
                alive[k] = 0;
                done[j] = 1;
                ++pivots;
                progress = true;
            }
            if (!progress) break;
        }
    }
    for (auto& x : alive) x = !x;
    return {pivots, bool_array(alive), bool_array(done)};
}

}  // namespace thesis

NB_MODULE(sparse_elimination, m) {
    m.doc() = "Integer homology by elimination: sparse Markowitz and dense unit-pivot elimination (thesis §2.2.1).";
    nanobind::class_<thesis::Options>(m, "Options", "The options of markowitz.")
        .def(nanobind::init<std::int64_t, std::int64_t, std::int64_t, double, std::int64_t>(), nanobind::arg("p"),
             nanobind::arg("lim"), nanobind::arg("search"), nanobind::arg("density"), nanobind::arg("max_dense"))
        .def_rw("p", &thesis::Options::p)
        .def_rw("lim", &thesis::Options::lim)
        .def_rw("search", &thesis::Options::search)
        .def_rw("density", &thesis::Options::density)
        .def_rw("max_dense", &thesis::Options::max_dense);
    m.def("markowitz", &thesis::markowitz, nanobind::arg("indptr"), nanobind::arg("indices"), nanobind::arg("data"),
          nanobind::arg("n_rows"), nanobind::arg("skip"), nanobind::arg("options"));
    m.def("dense_unit_elimination", &thesis::dense_unit_elimination, nanobind::arg("a").noconvert(),
          nanobind::arg("p"), nanobind::arg("lim"));
}
