// Discrete gradient vector fields (thesis chapter 4): greedy matchings, the topological order of
// V-paths and the Morse boundary by gradient paths.
#include "arrays.hpp"

#include <nanobind/stl/tuple.h>

#include <functional>
#include <queue>
#include <tuple>
#include <utility>

namespace thesis {

// int64 arithmetic that wraps around on overflow, as numba's does (signed overflow is UB in C++).
inline std::int64_t wrap_add(std::int64_t a, std::int64_t b) {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
inline std::int64_t wrap_mul(std::int64_t a, std::int64_t b) {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}
inline std::int64_t wrap_neg(std::int64_t a) { return static_cast<std::int64_t>(0 - static_cast<std::uint64_t>(a)); }

// Refuse a CSR graph on n nodes whose ptr (n + 1,) is not non-decreasing from >= 0 within idx, or
// whose idx[ptr[0]:ptr[n]] (and idx[0:ptr[n]]) leave 0..n-1.
void check_csr(const char* who, std::int64_t n, const In<std::int64_t, nb::ndim<1>>& ptr,
               const In<std::int64_t, nb::ndim<1>>& idx) {
    if (n < 0) throw std::invalid_argument(std::string(who) + ": n must be non-negative");
    if (static_cast<std::int64_t>(ptr.shape(0)) != n + 1)
        throw std::invalid_argument(std::string(who) + ": ptr must have n + 1 entries");
    const std::int64_t* P = ptr.data();
    if (P[0] < 0) throw std::invalid_argument(std::string(who) + ": ptr[0] must be non-negative");
    for (std::int64_t v = 0; v < n; ++v)
        if (P[v + 1] < P[v]) throw std::invalid_argument(std::string(who) + ": ptr must be non-decreasing");
    if (P[n] > static_cast<std::int64_t>(idx.shape(0)))
        throw std::invalid_argument(std::string(who) + ": ptr[n] exceeds the length of idx");
    const std::int64_t* I = idx.data();
    for (std::int64_t e = 0; e < P[n]; ++e)
        if (I[e] < 0 || I[e] >= n) throw std::invalid_argument(std::string(who) + ": an index is outside 0..n-1");
}

// Kahn's algorithm on the digraph (CSR ptr/idx): rank[v] = position, -1 if on or after a cycle.
// Thesis: Theorem 4.36 (a discrete vector field is a gradient iff it has no closed V-path).
Array<std::int64_t> topological_rank(std::int64_t n, In<std::int64_t, nb::ndim<1>> ptr,
                                     In<std::int64_t, nb::ndim<1>> idx) {
    check_csr("topological_rank", n, ptr, idx);
    const std::int64_t* P = ptr.data();
    const std::int64_t* I = idx.data();
    std::vector<std::int64_t> rank(static_cast<std::size_t>(n), -1);
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> indeg(static_cast<std::size_t>(n), 0);
        for (std::int64_t e = 0; e < P[n]; ++e) indeg[I[e]] += 1;
        std::vector<std::int64_t> queue(static_cast<std::size_t>(n));
        std::int64_t head = 0, tail = 0;
        for (std::int64_t v = 0; v < n; ++v)
            if (indeg[v] == 0) queue[tail++] = v;
        while (head < tail) {
            const std::int64_t v = queue[head];
            rank[v] = head;
            ++head;
            for (std::int64_t e = P[v]; e < P[v + 1]; ++e) {
                const std::int64_t w = I[e];
                if (--indeg[w] == 0) {
                    if (tail >= n) impossible("topological_rank: queue overflow");
                    queue[tail++] = w;
                }
            }
        }
    }
    return to_numpy(std::move(rank));
}

// Greedy coreduction (down = faces) or collapse (down = cofaces) restricted to equal vals: a cell
// whose single remaining down neighbour (of equal value) is σ is paired with σ and both are removed;
// when there is no such cell, the first remaining cell of order is made critical.  Returns partner
// (-1 for critical cells).
// Thesis: §4.3 (coreductions and collapses give acyclic matchings, Theorem 4.36).
Array<std::int64_t> greedy_matching(std::int64_t n, In<std::int64_t, nb::ndim<1>> down_ptr,
                                    In<std::int64_t, nb::ndim<1>> down_idx, In<std::int64_t, nb::ndim<1>> up_ptr,
                                    In<std::int64_t, nb::ndim<1>> up_idx, In<double, nb::ndim<1>> vals,
                                    In<std::int64_t, nb::ndim<1>> order) {
    check_csr("greedy_matching", n, down_ptr, down_idx);
    check_csr("greedy_matching", n, up_ptr, up_idx);
    if (static_cast<std::int64_t>(vals.shape(0)) != n || static_cast<std::int64_t>(order.shape(0)) != n)
        throw std::invalid_argument("greedy_matching: vals and order must have n entries");
    const std::int64_t* O = order.data();
    for (std::int64_t i = 0; i < n; ++i)
        if (O[i] < 0 || O[i] >= n) throw std::invalid_argument("greedy_matching: order is outside 0..n-1");
    const std::int64_t *DP = down_ptr.data(), *DI = down_idx.data(), *UP = up_ptr.data(), *UI = up_idx.data();
    const double* V = vals.data();
    std::vector<std::int64_t> partner(static_cast<std::size_t>(n), -1);
    bool bad_order = false;
    {
        nb::gil_scoped_release release;
        std::vector<char> removed(static_cast<std::size_t>(n), 0);
        std::vector<std::int64_t> cnt(static_cast<std::size_t>(n), 0);
        for (std::int64_t g = 0; g < n; ++g) {
            std::int64_t c = 0;
            for (std::int64_t e = DP[g]; e < DP[g + 1]; ++e)
                if (V[DI[e]] == V[g]) ++c;
            cnt[g] = c;
        }
        std::vector<std::int64_t> queue;
        queue.reserve(static_cast<std::size_t>(2 * n + 1));
        std::size_t head = 0;
        for (std::int64_t g = 0; g < n; ++g)
            if (cnt[g] == 1) queue.push_back(g);
        std::int64_t pointer = 0, done = 0;
        std::int64_t gone[2] = {0, 0};  // the cells removed in this step: a pair (σ, g), or one critical cell
        while (done < n) {
            int n_gone;
            if (head < queue.size()) {
                const std::int64_t g = queue[head++];
                if (removed[g] || cnt[g] != 1) continue;
                std::int64_t s = -1;
                for (std::int64_t e = DP[g]; e < DP[g + 1]; ++e) {
                    const std::int64_t j = DI[e];
                    if (V[j] == V[g] && !removed[j]) {
                        s = j;
                        break;
                    }
                }
                if (s < 0) impossible("greedy_matching: no remaining neighbour (down and up lists disagree)");
                partner[g] = s;
                partner[s] = g;
                gone[0] = s, gone[1] = g;
                n_gone = 2;
            } else {
                while (pointer < n && removed[O[pointer]]) ++pointer;
                if (pointer >= n) {
                    bad_order = true;  // order is not a permutation
                    break;
                }
                gone[0] = O[pointer];
                n_gone = 1;
            }
            for (int kk = 0; kk < n_gone; ++kk) {
                const std::int64_t c = gone[kk];
                removed[c] = 1;
                ++done;
                for (std::int64_t e = UP[c]; e < UP[c + 1]; ++e) {
                    const std::int64_t h = UI[e];
                    if (!removed[h] && V[h] == V[c]) {
                        if (--cnt[h] == 1) queue.push_back(h);
                    }
                }
            }
        }
    }
    if (bad_order) throw std::invalid_argument("greedy_matching: order must be a permutation of 0..n-1");
    return to_numpy(std::move(partner));
}

// A discrete gradient on the n cells: each cell's partner (−1: unpaired), its rank in the topological
// order of the V-path graph, and whether it is critical.
struct Gradient {
    In<std::int64_t, nb::ndim<1>> partner, rank;
    In<bool, nb::ndim<1>> is_crit;
};

// Theorem 4.42 for every critical cell in sources: flow ∂τ along gradient paths.  Up-paired k-cells
// are eliminated in topological order of the V-path graph (a heap on (rank, id)); the coefficients
// left on critical cells are the sums of multiplicities ±1 over gradient paths (mod p if p > 0).
// Returns COO triples (rows, cols, vals) in global ids and an overflow flag (|entry| > 2^60 over Z).
// Thesis: Theorem 4.42 (the Morse boundary), Theorem 4.44 (the modified Hasse diagram).
std::tuple<Array<std::int64_t>, Array<std::int64_t>, Array<std::int64_t>, bool> morse_columns(
    std::int64_t n, In<std::int64_t, nb::ndim<1>> ptr, In<std::int64_t, nb::ndim<1>> idx,
    In<std::int64_t, nb::ndim<1>> data, const Gradient& gradient, In<std::int64_t, nb::ndim<1>> sources,
    std::int64_t p) {
    const In<std::int64_t, nb::ndim<1>>& partner = gradient.partner;
    const In<std::int64_t, nb::ndim<1>>& rank = gradient.rank;
    const In<bool, nb::ndim<1>>& is_crit = gradient.is_crit;
    check_csr("morse_columns", n, ptr, idx);
    const std::int64_t* P = ptr.data();
    if (static_cast<std::int64_t>(data.shape(0)) < P[n])
        throw std::invalid_argument("morse_columns: data must be as long as idx");
    if (static_cast<std::int64_t>(partner.shape(0)) != n || static_cast<std::int64_t>(rank.shape(0)) != n ||
        static_cast<std::int64_t>(is_crit.shape(0)) != n)
        throw std::invalid_argument("morse_columns: partner, rank and is_crit must have n entries");
    const std::int64_t *I = idx.data(), *DA = data.data(), *PA = partner.data(), *RK = rank.data(),
                       *SR = sources.data();
    const bool* CR = is_crit.data();
    for (std::int64_t i = 0; i < n; ++i)
        if (PA[i] < -1 || PA[i] >= n) throw std::invalid_argument("morse_columns: partner is outside -1..n-1");
    const std::int64_t n_sources = static_cast<std::int64_t>(sources.shape(0));
    for (std::int64_t i = 0; i < n_sources; ++i)
        if (SR[i] < 0 || SR[i] >= n) throw std::invalid_argument("morse_columns: a source is outside 0..n-1");
    const std::int64_t limit = std::int64_t(1) << 60;
    bool overflow = false;
    std::vector<std::int64_t> out_r, out_c, out_v;
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> acc(static_cast<std::size_t>(n), 0);
        std::vector<char> inheap(static_cast<std::size_t>(n), 0);
        std::vector<std::int64_t> touched(static_cast<std::size_t>(n));
        using Item = std::pair<std::int64_t, std::int64_t>;  // (rank, cell): heapq's tuple order
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
        for (std::int64_t it = 0; it < n_sources; ++it) {
            const std::int64_t t = SR[it];
            std::int64_t nt = 0;
            for (std::int64_t e = P[t]; e < P[t + 1]; ++e) {
                const std::int64_t s = I[e];
                acc[s] = wrap_add(acc[s], DA[e]);
                if (!inheap[s]) {
                    inheap[s] = 1;
                    touched[nt++] = s;
                    if (PA[s] > s) heap.emplace(RK[s], s);
                }
            }
            while (!heap.empty()) {
                const std::int64_t s = heap.top().second;
                heap.pop();
                std::int64_t a = acc[s];
                if (p > 0) a = floor_mod(a, p);
                if (a == 0) continue;
                const std::int64_t tau = PA[s];
                std::int64_t sgn = 0;
                for (std::int64_t e = P[tau]; e < P[tau + 1]; ++e)
                    if (I[e] == s) sgn = DA[e];
                const std::int64_t factor = wrap_mul(wrap_neg(a), sgn);
                for (std::int64_t e = P[tau]; e < P[tau + 1]; ++e) {
                    const std::int64_t s2 = I[e];
                    acc[s2] = wrap_add(acc[s2], wrap_mul(factor, DA[e]));
                    if (p > 0)
                        acc[s2] = floor_mod(acc[s2], p);
                    else if (acc[s2] > limit || acc[s2] < -limit)
                        overflow = true;
                    if (!inheap[s2]) {
                        inheap[s2] = 1;
                        touched[nt++] = s2;
                        if (PA[s2] > s2) heap.emplace(RK[s2], s2);
                    }
                }
            }
            for (std::int64_t i = 0; i < nt; ++i) {
                const std::int64_t s = touched[i];
                std::int64_t a = acc[s];
                if (p > 0) a = floor_mod(a, p);
                if (CR[s] && a != 0) {
                    out_r.push_back(s);
                    out_c.push_back(t);
                    out_v.push_back(a);
                }
                acc[s] = 0;
                inheap[s] = 0;
            }
        }
    }
    return {to_numpy(std::move(out_r)), to_numpy(std::move(out_c)), to_numpy(std::move(out_v)), overflow};
}

}  // namespace thesis

NB_MODULE(discrete_gradient, m) {
    namespace nb = nanobind;
    m.doc() = "Discrete gradient vector fields: greedy matchings, V-path order, Morse boundary (thesis chapter 4).";
    m.def("topological_rank", &thesis::topological_rank, nb::arg("n"), nb::arg("ptr"), nb::arg("idx"));
    m.def("greedy_matching", &thesis::greedy_matching, nb::arg("n"), nb::arg("down_ptr"), nb::arg("down_idx"),
          nb::arg("up_ptr"), nb::arg("up_idx"), nb::arg("vals"), nb::arg("order"));
    nb::class_<thesis::Gradient>(m, "Gradient", "A discrete gradient: each cell's partner, rank and criticality.")
        .def(nb::init<thesis::In<std::int64_t, nb::ndim<1>>, thesis::In<std::int64_t, nb::ndim<1>>,
                      thesis::In<bool, nb::ndim<1>>>(),
             nb::arg("partner"), nb::arg("rank"), nb::arg("is_crit"));
    m.def("morse_columns", &thesis::morse_columns, nb::arg("n"), nb::arg("ptr"), nb::arg("idx"), nb::arg("data"),
          nb::arg("gradient"), nb::arg("sources"), nb::arg("p"));
}
