// The implicit Vietoris–Rips persistence engine: the barcode of a Rips filtration without storing its
// simplices (Ripser's reduction, Bauer 2021, on the cohomology side with clearing, apparent and
// emergent pairs; the port of thesis_lib/persistence/implicit.py's kernels).
//
// H0 by union–find over the edges in filtration order; in each dimension k >= 1 the k-simplices are
// met as cofaces of the (k−1)-simplices (in parallel), those not cleared and not in a zero apparent
// pair become coboundary columns, reduced latest first, with a lazy working column: a heap of coboundary enumerators, one
// per added coboundary f · δs, each yielding the cofaces of s in filtration order (diameter up,
// index down).  The graph and the combinatorial number system are in implicit_rips_graph.hpp; on
// request each bar's reduction chain is returned as its representative cocycle
// (implicit_rips_cocycles.hpp).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>

#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include "arrays.hpp"
#include "column_heap.hpp"
#include "implicit_rips_cocycles.hpp"
#include "implicit_rips_graph.hpp"
#include "union_find.hpp"

namespace thesis {
namespace rips {

// ---------------------------------------------------------------------------- the graph
// Symmetric neighbour lists from the edges (u, v), each list sorted by decreasing neighbour.
// Thesis: Definition 2.11 (the edges of the Rips complex, diameter <= 2 eps).
std::tuple<Array<i64>, Array<i64>, Array<double>> neighbour_lists(i64 n, In<i64, nb::ndim<2>> edges,
                                                                  In<double, nb::ndim<1>> lengths) {
    if (n < 0) throw std::invalid_argument("neighbour_lists: n must be >= 0");
    if (edges.shape(1) != 2) throw std::invalid_argument("neighbour_lists: edges must have shape (m, 2)");
    if (lengths.shape(0) != edges.shape(0))
        throw std::invalid_argument("neighbour_lists: lengths must have one entry per edge");
    const i64 m = static_cast<i64>(edges.shape(0));
    const i64* E = edges.data();
    const double* L = lengths.data();
    for (i64 e = 0; e < 2 * m; ++e)
        if (E[e] < 0 || E[e] >= n) throw std::invalid_argument("neighbour_lists: an edge has a vertex outside 0 .. n - 1");
    std::vector<i64> indptr(static_cast<std::size_t>(n + 1), 0), nbr;
    std::vector<double> length;
    {
        nb::gil_scoped_release release;
        for (i64 e = 0; e < m; ++e) {
            indptr[E[2 * e] + 1] += 1;
            indptr[E[2 * e + 1] + 1] += 1;
        }
        for (i64 v = 0; v < n; ++v) indptr[v + 1] += indptr[v];
        std::vector<i64> fill(indptr.begin(), indptr.end() - 1);
        nbr.resize(static_cast<std::size_t>(indptr[n]));
        length.resize(static_cast<std::size_t>(indptr[n]));
        // edges (u, v) with u < v in any order: place v in u's list and u in v's, then sort each list
        for (i64 e = 0; e < m; ++e) {
            const i64 u = E[2 * e], v = E[2 * e + 1];
            nbr[fill[u]] = v;
            length[fill[u]] = L[e];
            ++fill[u];
            nbr[fill[v]] = u;
            length[fill[v]] = L[e];
            ++fill[v];
        }
        std::vector<i64> order;
        std::vector<i64> tn;
        std::vector<double> tl;
        for (i64 v = 0; v < n; ++v) {
            const i64 a = indptr[v], b = indptr[v + 1];
            bool rising = true;  // edges in lexicographic order (every source of ours) fill each list rising
            for (i64 e = a + 1; e < b; ++e) {
                if (nbr[e] <= nbr[e - 1]) {
                    rising = false;
                    break;
                }
            }
            if (rising) {
                std::reverse(nbr.begin() + a, nbr.begin() + b);
                std::reverse(length.begin() + a, length.begin() + b);
            } else {  // by decreasing neighbour, ties (repeated edges) in their order
                order.resize(static_cast<std::size_t>(b - a));
                for (i64 e = a; e < b; ++e) order[e - a] = e;
                std::stable_sort(order.begin(), order.end(), [&](i64 x, i64 y) { return nbr[x] > nbr[y]; });
                tn.resize(order.size());
                tl.resize(order.size());
                for (std::size_t t = 0; t < order.size(); ++t) {
                    tn[t] = nbr[order[t]];
                    tl[t] = length[order[t]];
                }
                std::copy(tn.begin(), tn.end(), nbr.begin() + a);
                std::copy(tl.begin(), tl.end(), length.begin() + a);
            }
        }
    }
    const std::size_t total = nbr.size();
    return {to_numpy(std::move(indptr)), to_numpy(std::move(nbr), {total}), to_numpy(std::move(length), {total})};
}

// The graph's lists sorted by increasing distance, ties by decreasing neighbour (for the apparent
// pairs and the far cofaces), and the dense matrix when asked for.
void prepare(Graph& g, bool dense) {
    const i64 n = g.n;
    const i64 total = g.indptr[n];
    g.dnbr.resize(static_cast<std::size_t>(total));
    g.dlen.resize(static_cast<std::size_t>(total));
    std::vector<i64> order;
    for (i64 v = 0; v < n; ++v) {
        const i64 a = g.indptr[v], b = g.indptr[v + 1];
        order.resize(static_cast<std::size_t>(b - a));
        for (i64 e = a; e < b; ++e) order[e - a] = e;
        std::sort(order.begin(), order.end(), [&](i64 x, i64 y) {
            return g.length[x] < g.length[y] || (g.length[x] == g.length[y] && g.nbr[x] > g.nbr[y]);
        });
        for (i64 t = 0; t < b - a; ++t) {
            g.dnbr[a + t] = g.nbr[order[t]];
            g.dlen[a + t] = g.length[order[t]];
        }
    }
    g.dense = dense;
    if (dense) {
        g.D.assign(static_cast<std::size_t>(n * n), kInf);
        for (i64 u = 0; u < n; ++u)
            for (i64 e = g.indptr[u]; e < g.indptr[u + 1]; ++e) g.D[u * n + g.nbr[e]] = g.length[e];
    } else {
        int bits = 4;
        while ((u64(1) << bits) < static_cast<u64>(total) + 2) ++bits;  // total = 2 · edges: load <= 1/2
        g.H.assign(u64(1) << bits, {-1, 0.0});
        g.hmask = (u64(1) << bits) - 1;
        g.hshift = 64 - bits;
        for (i64 u = 0; u < n; ++u) {
            for (i64 e = g.indptr[u + 1] - 1; e >= g.indptr[u] && g.nbr[e] < u; --e) {
                const i64 key = u * n + g.nbr[e];
                g.H[g.hslot(key)] = {key, g.length[e]};
            }
        }
    }
}

// ---------------------------------------------------------------------------- dimension 0
// Every edge as (diameter, index = C(u, 2) + v for u > v), by increasing index.
void edges_by_index(const Graph& g, std::vector<double>& ed, std::vector<i64>& ei) {
    ed.clear();
    ei.clear();
    ed.reserve(static_cast<std::size_t>(g.indptr[g.n] / 2));
    ei.reserve(static_cast<std::size_t>(g.indptr[g.n] / 2));
    for (i64 u = 0; u < g.n; ++u) {
        for (i64 e = g.indptr[u + 1] - 1; e >= g.indptr[u]; --e) {  // neighbours increasing
            const i64 v = g.nbr[e];
            if (v >= u) break;
            ed.push_back(g.length[e]);
            ei.push_back(u * (u - 1) / 2 + v);
        }
    }
}

// One dimension's output as it is built: births, deaths and essential births, the statistics and the
// cocycles (returned as a DimResult, below).
struct DimOut {
    std::vector<double> births, deaths, ess;
    std::vector<i64> stats;
    CocycleList cocycles;
};

// Union–find over the edges in filtration order (diameter up, index down), the vertices born at
// vbirth (inf: not in the complex): the (birth, death) of each H0 class that dies (elder rule: of the
// two classes an edge joins, the younger dies) and the births of the components left, into out's bars,
// and the positive edges (those closing a cycle).
// Thesis: Definition 2.31 (elder rule), §2.3.4.
void h0(i64 n, const double* vbirth, const std::vector<double>& ed, const std::vector<i64>& ei, DimOut& out,
        std::vector<char>& positive) {
    std::vector<double>& births = out.births;
    std::vector<double>& deaths = out.deaths;
    std::vector<double>& ess = out.ess;
    const i64 m = static_cast<i64>(ed.size());
    std::vector<i64> order(static_cast<std::size_t>(m));
    for (i64 e = 0; e < m; ++e) order[e] = e;
    std::sort(order.begin(), order.end(),
              [&](i64 a, i64 b) { return ed[a] < ed[b] || (ed[a] == ed[b] && ei[a] > ei[b]); });
    std::vector<i64> parent(static_cast<std::size_t>(n));
    std::vector<double> born(vbirth, vbirth + n);  // the birth of each root's class
    for (i64 v = 0; v < n; ++v) parent[v] = v;
    births.clear();
    deaths.clear();
    positive.assign(static_cast<std::size_t>(m), 0);
    for (i64 t = 0; t < m; ++t) {
        const i64 e = order[t];
        i64 u = static_cast<i64>((1.0 + std::sqrt(1.0 + 8.0 * static_cast<double>(ei[e]))) / 2.0);
        while (u * (u - 1) / 2 > ei[e]) --u;  // ei = C(u, 2) + v with v < u
        while ((u + 1) * u / 2 <= ei[e]) ++u;
        i64 a = find(parent.data(), u);
        i64 b = find(parent.data(), ei[e] - u * (u - 1) / 2);
        if (a == b) {
            positive[e] = 1;
            continue;
        }
        if (a < b) std::swap(a, b);
        parent[a] = b;
        births.push_back(std::max(born[a], born[b]));
        deaths.push_back(ed[e]);
        born[b] = std::min(born[a], born[b]);
    }
    ess.clear();
    for (i64 v = 0; v < n; ++v)
        if (parent[v] == v && born[v] != kInf) ess.push_back(born[v]);
}

// ---------------------------------------------------------------------------- zero apparent pairs
// A pair s < tau of equal diameter is a zero apparent pair when tau is the earliest coface of s and s
// the latest facet of tau.  Both tests are local, so they are made where a simplex is met (as Ripser
// 1.2 does), and no table of the pairs is kept.

// Scratch space for the tests on simplices of dimension up to k + 2.
struct Scratch {
    std::vector<i64> verts, cur, w;
    explicit Scratch(i64 k)
        : verts(static_cast<std::size_t>(k + 3)), cur(static_cast<std::size_t>(k + 3)), w(static_cast<std::size_t>(k + 3)) {}
};

// The earliest coface of a simplex when it has the simplex's diameter, whether the two form a zero
// apparent pair, and whether the coface is taken (the upper simplex of another one).
struct EarliestCoface {
    Coface coface;
    bool apparent, taken;
};

// The earliest coface tau of the k-simplex s (vertices verts, diameter d) when it has s's diameter
// (index −1 otherwise), and whether the two form a zero apparent pair: always when the new vertex is
// above s's (s omits tau's top vertex and has tau's diameter: the latest facet), else when tau's
// latest facet is s.  When they do not, taken says whether tau is the upper simplex of another zero
// apparent pair (e, tau) (e its latest facet), so that s cannot be paired with tau at once.
// Thesis: Definition 4.30 (a pair of the discrete gradient), Theorem 4.42's idea.
EarliestCoface earliest_equal_coface(const Graph& g, const i64* verts, i64 k, i64 s, double d, Scratch& x) {
    double od[1];
    i64 oi[1], oj[1];
    const CofaceBuffers one{x.cur.data(), od, oi, oj};
    const Coface t = zero_pivot_cofacet(g, verts, k, s, d, one);
    bool apparent = t.index != -1 && t.m == 0;
    bool taken = false;
    if (t.index != -1 && t.m > 0) {
        for (i64 r = 0; r < k + 2; ++r) x.w[r] = r < t.m ? verts[r] : (r == t.m ? t.j : verts[r - 1]);
        const i64 e = zero_pivot_facet(g, t.index, k + 1, d, x.w.data(), true);
        apparent = e == s;
        if (e != -1 && e != s) {
            vertices(g, e, k, x.verts.data());
            taken = zero_pivot_cofacet(g, x.verts.data(), k, e, d, one).index == t.index;
        }
    }
    return {t, apparent, taken};
}

// The k-simplex e with (e, tau) a zero apparent pair, for the (k + 1)-simplex tau of diameter d; −1
// when tau is the upper simplex of none.
// Thesis: Definition 4.30 (a pair of the discrete gradient).
i64 zero_apparent_facet(const Graph& g, i64 tau, i64 k, double d, Scratch& x) {
    const i64 e = zero_pivot_facet(g, tau, k + 1, d, x.w.data(), false);
    if (e == -1) return -1;
    vertices(g, e, k, x.verts.data());
    double od[1];
    i64 oi[1], oj[1];
    return zero_pivot_cofacet(g, x.verts.data(), k, e, d, {x.cur.data(), od, oi, oj}).index == tau ? e : -1;
}

// ---------------------------------------------------------------------------- the columns of a dimension
// A simplex: its diameter and index.  A column to reduce: its simplex, the earliest coface when that
// has the simplex's diameter and is the upper simplex of no zero apparent pair (else −1: no emergent
// pair) and the sign of that coface in the coboundary.
struct Simplex {
    double d;
    i64 idx;
};
struct Column {
    double d;
    i64 idx, tau, sign;
};

// One block's share of a dimension: its columns, its k-simplices and the upper simplices of its zero
// apparent pairs (both when a next dimension is built), the candidates met (k-simplices not
// cleared) and the zero apparent pairs among them.
struct Assembled {
    std::vector<Column> columns;
    std::vector<Simplex> all;
    std::vector<i64> uppers;
    i64 candidates = 0, apparent = 0;
};

// Simplices kept in blocks (one per thread's share), read as one sequence.
struct Blocks {
    std::vector<std::vector<Simplex>> parts;
    i64 size() const {
        i64 s = 0;
        for (const auto& p : parts) s += static_cast<i64>(p.size());
        return s;
    }
    // f(simplex) for the simplices lo .. hi − 1 of the sequence, in order.
    template <class F>
    void visit(i64 lo, i64 hi, F f) const {
        i64 start = 0;
        for (const auto& p : parts) {
            const i64 end = start + static_cast<i64>(p.size());
            for (i64 q = std::max(lo, start); q < std::min(hi, end); ++q) f(p[static_cast<std::size_t>(q - start)]);
            start = end;
        }
    }
};

// What one dimension k is assembled from: the blocks `from` of (k − levels)-simplices, whether the
// k-simplices met are kept (keep_all) and whether a dimension k + 1 follows (next), and the tables of
// dimension k − 1: its pivots (cleared) and the upper simplices of its zero apparent pairs (uppers).
struct Assembly {
    i64 k;
    const Blocks& from;
    i64 levels;
    bool keep_all, next;
    const Table& cleared;
    const Table& uppers;
};

// The columns of dimension k (of the assembly a) among the k-simplices met from the blocks lo .. hi − 1
// of `from`, which holds the (k − levels)-simplices: with levels 0 the k-simplices themselves; with 1 each (k − 1)-simplex
// f and its cofaces tau = f ∪ {j} with j above f's vertices are met (each k-simplex once, its
// vertices known); with 2 the (k − 1)-simplices f are met the same way from the (k − 2)-simplices,
// and not stored (the top dimension's facets, the largest list).  A simplex met is kept in all when
// keep_all; it is a candidate unless it is a pivot of dimension k − 1 (cleared) or the upper simplex
// of a zero apparent pair (e, tau) of dimension k − 1, and a column unless it is the lower simplex of
// one.  The upper simplices need no table when e = f: f is tau's latest facet exactly when the two
// have one diameter (f omits tau's top vertex), so the first such coface met from f is f's earliest
// coface and the pair's upper simplex, and the later ones are no upper simplex.  Only the pairs whose
// new vertex is below the lower simplex's top vertex are kept in uppers (when next: a dimension k + 1
// follows), and looked up only for the cofaces above f's diameter.
// Thesis: Algorithm 2 with clearing (Theorem 2.39's dual reduction), Definition 2.11 (a coface of a
// flag simplex is a common neighbour), Definitions 4.30–4.33 (apparent pairs).
void assemble_block(const Graph& g, const Assembly& a, i64 lo, i64 hi, i64 maxdeg, Assembled& out) {
    const i64 k = a.k, levels = a.levels;
    const bool keep_all = a.keep_all, next = a.next;
    const Blocks& from = a.from;
    const Table &cleared = a.cleared, &uppers = a.uppers;
    Scratch x(k);
    const std::size_t width = static_cast<std::size_t>(maxdeg + 1);
    std::vector<i64> sv(static_cast<std::size_t>(k + 1)), fv(static_cast<std::size_t>(k)),
        cur(static_cast<std::size_t>(k)), oi(width), oj(width), oi2, oj2;
    std::vector<double> od(width), od2;
    if (levels == 2) {
        oi2.resize(width);
        oj2.resize(width);
        od2.resize(width);
    }
    const CofaceBuffers level1{cur.data(), od.data(), oi.data(), oj.data()},
        level2{cur.data(), od2.data(), oi2.data(), oj2.data()};  // the cofaces of f; of a (k − 2)-simplex
    auto meet = [&](double d, i64 s, bool upper) {  // s of diameter d and vertices sv
        if (keep_all) out.all.push_back({d, s});
        if (upper || cleared.contains(s)) return;
        ++out.candidates;
        const EarliestCoface early = earliest_equal_coface(g, sv.data(), k, s, d, x);
        const Coface& t = early.coface;
        if (early.apparent) {
            ++out.apparent;
            if (next && t.m > 0) out.uppers.push_back(t.index);
        } else {
            out.columns.push_back({d, s, early.taken ? -1 : t.index, 1 - 2 * (t.m & 1)});
        }
    };
    auto above = [&](double fd, i64 fidx) {  // the cofaces of f (vertices fv) above its vertices
        std::copy(fv.begin(), fv.end(), sv.begin() + 1);
        const i64 c = cofaces(g, fv.data(), k - 1, fidx, fd, level1, false, true);
        bool first = true;  // no coface of f's diameter met yet
        for (i64 t = 0; t < c; ++t) {
            sv[0] = oj[t];
            if (od[t] == fd) {
                meet(od[t], oi[t], first);
                first = false;
            } else {
                meet(od[t], oi[t], uppers.contains(oi[t]));
            }
        }
    };
    // The vertices of the simplex idx of nv vertices into v; after a sibling (the same vertices below
    // its top, index rest without its top vertex) only the top vertex is decoded.
    auto decode = [&](i64 idx, i64 nv, i64* v, i64& rest) {
        v[0] = top_vertex(g, idx, nv, g.n - 1);
        const i64 below = wsub(idx, g.binom(v[0], nv));
        if (below != rest) {
            vertices(g, below, nv - 2, v + 1, v[0] - 1);
            rest = below;
        }
    };
    if (levels == 1 && keep_all)  // about the mean degree over k + 1 cofaces above each f (reserved, not touched)
        out.all.reserve(static_cast<std::size_t>((hi - lo) * g.indptr[g.n] / (g.n * (k + 1)) + 16));
    i64 rest = -1;
    std::vector<i64> hv(static_cast<std::size_t>(k > 1 ? k - 1 : 1));
    from.visit(lo, hi, [&](const Simplex& f) {
        if (levels == 0) {
            vertices(g, f.idx, k, sv.data());
            meet(f.d, f.idx, uppers.contains(f.idx));
        } else if (levels == 1) {
            decode(f.idx, k, fv.data(), rest);
            above(f.d, f.idx);
        } else {  // f is a (k − 2)-simplex: its cofaces above it are the facets met
            decode(f.idx, k - 1, hv.data(), rest);
            const i64 c = cofaces(g, hv.data(), k - 2, f.idx, f.d, level2, false, true);
            std::copy(hv.begin(), hv.end(), fv.begin() + 1);
            for (i64 t = 0; t < c; ++t) {
                fv[0] = oj2[t];
                above(od2[t], oi2[t]);
            }
        }
    });
}

// assemble_block over all of a.from: on one thread when fewer than parallel_min k-simplices are to be
// met (estimated as |from| times the mean degree over k + 1 per level, over k for a second), else in
// 8 · threads blocks shared by the threads; the blocks' shares are kept in block order, so nothing
// depends on how the blocks were shared.
std::vector<Assembled> assemble(const Graph& g, const Assembly& a, i64 maxdeg, int threads, i64 parallel_min) {
    const i64 k = a.k, levels = a.levels;
    const i64 m = a.from.size();
    const double degree = static_cast<double>(g.indptr[g.n]) / static_cast<double>(g.n);
    double met = static_cast<double>(m);
    for (i64 l = 0; l < levels; ++l) met *= degree / static_cast<double>(k + 1 - l);
    const i64 nblocks = (met < static_cast<double>(parallel_min) || threads <= 1) ? 1 : 8 * static_cast<i64>(threads);
    const i64 size = (m + nblocks - 1) / nblocks;
    std::vector<Assembled> out(static_cast<std::size_t>(nblocks));
    std::atomic<i64> taken{0};
    const int workers = static_cast<int>(std::min<i64>(threads, nblocks));
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(workers));
    auto work = [&](int t) {
        try {
            for (i64 b = taken++; b < nblocks; b = taken++)
                assemble_block(g, a, std::min(m, b * size), std::min(m, (b + 1) * size), maxdeg,
                               out[static_cast<std::size_t>(b)]);
        } catch (...) {
            errors[static_cast<std::size_t>(t)] = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < workers; ++t) pool.emplace_back(work, t);
    work(0);
    for (auto& th : pool) th.join();
    for (auto& err : errors)
        if (err) std::rethrow_exception(err);
    return out;
}

// ---------------------------------------------------------------------------- the reduction
// The working column of one dimension k: a heap of lazy coboundary enumerators (see implicit.py).
// An enumerator's row of S (width 2k + 8): the vertices of s (decreasing), k + 1 list positions, the
// base vertex, the phase, the factor f, a coface index to skip (the pivot being cancelled) or −1, the
// head's key (−index) and coefficient; of F: the diameter of s and the head's diameter.  Phases: the
// cofaces of s's own diameter d by a scan of the base vertex's neighbours (0) or by selection from
// its distance-sorted prefix (1), then the others by merging the distance-sorted lists (2).
// Thesis: §2.3.5, the column of Algorithm 1 being reduced, summed lazily (Bauer 2021).
class Reducer {
  public:
    Reducer(const Graph& g, i64 k, i64 p)
        : g_(g), k_(k), p_(p), w_(2 * k + 8), S_(static_cast<std::size_t>(64 * (2 * k + 8))), F_(128), heap(64) {}

    ColumnHeap<double, i64, i64> heap;  // heads: (diameter, −index, enumerator)
    i64 nr = 0;                         // enumerators in use

    void clear() {
        nr = 0;
        heap.clear();
    }

    // Add f · δs (without skip) to the working column: a new enumerator, its head on the heap.
    void add(i64 s, i64 f, i64 skip, double ds) {
        if (static_cast<std::size_t>(nr * w_) == S_.size()) {
            S_.resize(2 * S_.size());
            F_.resize(2 * F_.size());
        }
        if (open(nr, s, f, skip, ds)) {
            heap.push(F_[2 * nr + 1], S_[nr * w_ + 2 * k_ + 6], nr);
            ++nr;
        }
    }

    // The pivot of the working column, removed from it: (diameter, key, coefficient); coefficient 0
    // when the column is zero.  read counts the heads popped.
    Pivot<double, i64, i64> pop_pivot(i64& read) {
        while (heap.size > 0) {
            const double v = heap.value[0];
            const i64 key = heap.key[0];
            i64 c = 0;
            while (heap.size > 0 && heap.key[0] == key) {
                const i64 r = heap.coef[0];
                c += S_[r * w_ + 2 * k_ + 7];
                ++read;
                if (advance(r))
                    heap.replace_top(F_[2 * r + 1], S_[r * w_ + 2 * k_ + 6], r);
                else
                    heap.pop();
            }
            c %= p_;
            if (c != 0) return {v, key, c};
        }
        return {kInf, 0, 0};
    }

  private:
    const Graph& g_;
    const i64 k_, p_, w_;
    std::vector<i64> S_;
    std::vector<double> F_;

    // Index of s ∪ {j} (s the vertices in row r) and m = #vertices of s above j.
    i64 coface_index(const i64* row, i64 j, i64& m) const {
        i64 idx = 0;
        m = 0;
        for (i64 q = 0; q <= k_; ++q) {
            const i64 v = row[q];
            if (v > j) {
                idx = wadd(idx, g_.binom(v, k_ + 2 - q));
                ++m;
            } else {
                idx = wadd(idx, g_.binom(v, k_ + 1 - q));
            }
        }
        return wadd(idx, g_.binom(j, k_ + 2 - m));
    }

    // Make s ∪ {j} (diameter d) the head of enumerator r; false when it is the one to skip.
    bool emit(i64 r, i64 j, double d) {
        i64* row = &S_[r * w_];
        i64 m;
        const i64 idx = coface_index(row, j, m);
        if (idx == row[2 * k_ + 5]) return false;
        row[2 * k_ + 6] = -idx;
        const i64 f = row[2 * k_ + 4];
        row[2 * k_ + 7] = (m & 1) == 0 ? f : p_ - f;
        F_[2 * r + 1] = d;
        return true;
    }

    // Enter phase 2: each list position just past the neighbours within s's diameter.
    void start_far(i64 r) {
        i64* row = &S_[r * w_];
        const double d = F_[2 * r];
        for (i64 q = 0; q <= k_; ++q) {
            const i64 v = row[q];
            row[k_ + 1 + q] = upper(g_.dlen.data(), g_.indptr[v], g_.indptr[v + 1], d);
        }
        row[2 * k_ + 3] = 2;
    }

    // Move enumerator r to its next coface; false when it has none left.
    bool advance(i64 r) {
        const i64 P0 = k_ + 1, AUX = 2 * k_ + 2, PH = 2 * k_ + 3;
        const i64* indptr = g_.indptr;
        const i64* dnbr = g_.dnbr.data();
        const double* dlen = g_.dlen.data();
        i64* row = &S_[r * w_];
        const double d = F_[2 * r];
        for (;;) {
            const i64 ph = row[PH];
            if (ph == 0) {  // cofaces of diameter d, by a scan of the base vertex's neighbours (j decreasing)
                const i64 b = row[AUX];
                i64 e = row[P0 + b];
                const i64 end = indptr[row[b] + 1];
                while (e < end) {
                    const i64 j = g_.nbr[e];
                    const double le = g_.length[e];
                    ++e;
                    if (le > d) continue;
                    bool ok = true;
                    for (i64 q = 0; q <= k_; ++q) {
                        if (q != b && g_.dist(row[q], j) > d) {
                            ok = false;
                            break;
                        }
                    }
                    if (ok && emit(r, j, d)) {
                        row[P0 + b] = e;
                        return true;
                    }
                }
                start_far(r);
            } else if (ph == 1) {  // the same set by selection: the largest j below the last one emitted
                const i64 b = row[AUX];
                const i64 vb = row[b];
                const i64 last = row[P0];
                const i64 hi = row[P0 + 1];
                i64 best = -1;
                for (i64 e = indptr[vb]; e < hi; ++e) {
                    const i64 j = dnbr[e];
                    if (j >= last || j <= best) continue;
                    bool ok = true;
                    for (i64 q = 0; q <= k_; ++q) {
                        if (q != b && g_.dist(row[q], j) > d) {
                            ok = false;
                            break;
                        }
                    }
                    if (ok) best = j;
                }
                if (best == -1) {
                    start_far(r);
                    continue;
                }
                row[P0] = best;
                if (emit(r, best, d)) return true;
            } else if (ph == 2) {  // the far cofaces: merge the distance-sorted lists by (distance, −neighbour)
                for (;;) {
                    i64 qi = -1;
                    double bd = kInf;
                    i64 bj = -1;
                    for (i64 q = 0; q <= k_; ++q) {
                        const i64 c = row[P0 + q];
                        if (c < indptr[row[q] + 1]) {
                            const double x = dlen[c];
                            if (qi == -1 || x < bd || (x == bd && dnbr[c] > bj)) {
                                qi = q;
                                bd = x;
                                bj = dnbr[c];
                            }
                        }
                    }
                    if (qi == -1) {
                        row[PH] = 3;
                        return false;
                    }
                    row[P0 + qi] += 1;
                    bool ok = true;
                    for (i64 q = 0; q <= k_; ++q) {
                        if (q != qi) {
                            const double x = g_.dist(row[q], bj);
                            if (x > bd || (x == bd && q > qi)) {
                                ok = false;
                                break;
                            }
                        }
                    }
                    if (ok && emit(r, bj, bd)) return true;
                }
            } else {
                return false;
            }
        }
    }

    // Set up enumerator r for f · δs without the coface skip; false when it yields nothing.
    bool open(i64 r, i64 s, i64 f, i64 skip, double ds) {
        i64* row = &S_[r * w_];
        vertices(g_, s, k_, row);
        F_[2 * r] = ds;
        row[2 * k_ + 4] = f;
        row[2 * k_ + 5] = skip;
        i64 b = 0;
        i64 cb = i64(1) << 62;
        for (i64 q = 0; q <= k_; ++q) {  // the base: the vertex with the fewest neighbours within ds
            const i64 v = row[q];
            const i64 c = upper(g_.dlen.data(), g_.indptr[v], g_.indptr[v + 1], ds) - g_.indptr[v];
            if (c < cb) {
                cb = c;
                b = q;
            }
        }
        const i64 vb = row[b];
        row[2 * k_ + 2] = b;
        if (cb == 0) {
            start_far(r);
        } else if (cb * cb <= g_.degree(vb)) {
            row[2 * k_ + 3] = 1;
            row[k_ + 1] = g_.n;  // last j emitted: none yet
            row[k_ + 2] = g_.indptr[vb] + cb;
        } else {
            row[2 * k_ + 3] = 0;
            row[k_ + 1 + b] = g_.indptr[vb];
        }
        return advance(r);
    }
};

// The outcome of one dimension's reduction: the finite bars, the essential ones, their cocycles (when
// asked for, in the same orders) and the statistics.
struct Reduced {
    std::vector<double> births, deaths, ess;
    CocycleList finite, essential;
    Table pivots{0};
    i64 emergent = 0, worked = 0, additions = 0, read = 0, most = 0;
};

// Reduce the coboundary columns of the k-simplices cols (latest first) over Z/p: each column's tau and
// sign are its earliest coface when that may make an emergent pair (else −1) and its sign; the
// pivots of zero apparent pairs met are found by zero_apparent_facet.  With cocycles, the chain V of
// each column that gives a bar (of positive length, or essential) is kept as its representative.
// Thesis: Algorithm 1 (Reduce) inside Algorithm 2, §2.3.5, on the cohomology side (Theorem 2.39),
// with emergent and apparent pairs (Definitions 4.30–4.33).
Reduced reduce(const Graph& g, i64 k, const std::vector<Column>& cols, i64 p, bool cocycles) {
    const i64 ncol = static_cast<i64>(cols.size());
    Reduced out;
    out.pivots = Table(ncol);
    Table& piv_t = out.pivots;
    std::vector<i64> pcoef(static_cast<std::size_t>(ncol), 0), vstart(static_cast<std::size_t>(ncol), -1),
        vlen(static_cast<std::size_t>(ncol), 0);
    std::vector<i64> pool_s, pool_c;
    std::vector<double> pool_d;
    std::vector<i64> verts(static_cast<std::size_t>(k + 2)), w(static_cast<std::size_t>(k + 2));
    std::vector<i64> wk, wc, pos, sums;
    std::vector<double> wd;
    Reducer col(g, k, p);
    Scratch x(k);
    for (i64 c = 0; c < ncol; ++c) {
        const i64 s = cols[c].idx;
        const double ds = cols[c].d;
        const i64 t = cols[c].tau;
        if (t != -1) {  // emergent pair: the earliest coface has s's diameter and nobody owns it
            const i64 h = piv_t.slot(t);
            if (piv_t.keys[h] == -1) {
                piv_t.keys[h] = t;
                piv_t.vals[h] = c;
                pcoef[c] = floor_mod(cols[c].sign, p);
                ++out.emergent;
                continue;
            }
        }
        col.clear();
        col.add(s, 1, -1, ds);
        wk.clear();
        wc.clear();
        wd.clear();
        i64 piv = -1;
        bool bar = false;  // a finite bar of positive length
        for (;;) {
            const Pivot<double, i64, i64> pv = col.pop_pivot(out.read);
            if (pv.coef == 0) {  // the column is zero: s creates an essential class
                piv = -1;
                break;
            }
            piv = -pv.key;
            const i64 h = piv_t.slot(piv);
            if (piv_t.keys[h] != -1) {  // add the column owning this pivot: factor · Σ_{s' in V_o} δ(s')
                const i64 o = piv_t.vals[h];
                const i64 factor = (p - pv.coef * mod_inverse(pcoef[o], p) % p) % p;
                const i64 ol = vstart[o] == -1 ? 1 : vlen[o] + 1;
                for (i64 q = 0; q < ol; ++q) {
                    i64 so, co;
                    double dso;
                    if (q == 0) {
                        so = cols[o].idx;
                        co = 1;
                        dso = cols[o].d;
                    } else {
                        so = pool_s[vstart[o] + q - 1];
                        co = pool_c[vstart[o] + q - 1];
                        dso = pool_d[vstart[o] + q - 1];
                    }
                    const i64 f = factor * co % p;
                    wk.push_back(so);
                    wc.push_back(f);
                    wd.push_back(dso);
                    col.add(so, f, piv, dso);
                }
                ++out.additions;
                continue;
            }
            const i64 e = zero_apparent_facet(g, piv, k, pv.value, x);
            if (e != -1) {  // pivot of a zero apparent pair (e, tau): add δe, the column of e
                const double de = pv.value;  // the pair has equal diameters
                vertices(g, piv, k + 1, w.data());
                vertices(g, e, k, verts.data());
                i64 r = 0;
                while (r <= k && w[r] == verts[r]) ++r;
                const i64 se = (r & 1) == 0 ? 1 : p - 1;  // coefficient of tau in δe: (−1)^r
                const i64 factor = (p - pv.coef * mod_inverse(se, p) % p) % p;
                wk.push_back(e);
                wc.push_back(factor);
                wd.push_back(de);
                col.add(e, factor, piv, de);
                ++out.additions;
                continue;
            }
            // the pivot is free: (s, tau) is a persistence pair
            if (pv.value > ds) {
                out.births.push_back(ds);
                out.deaths.push_back(pv.value);
                bar = true;
            }
            piv_t.keys[h] = piv;
            piv_t.vals[h] = c;
            pcoef[c] = pv.coef;
            break;
        }
        out.most = std::max(out.most, col.nr);
        const i64 wn = static_cast<i64>(wk.size());
        if (wn > 0) ++out.worked;
        if (cocycles && (bar || piv == -1))
            append_cocycle(g, k, p, s, ds, {wk.data(), wc.data(), wd.data(), wn}, piv == -1 ? out.essential : out.finite);
        if (piv == -1) {
            out.ess.push_back(ds);
            continue;
        }
        if (wn > 0) {  // store V_c (merged, zeros dropped; s itself is implicit) for later additions
            merge_entries(wk.data(), wc.data(), wn, p, pos, sums);
            vstart[c] = static_cast<i64>(pool_s.size());
            for (std::size_t q = 0; q < pos.size(); ++q) {
                pool_s.push_back(wk[pos[q]]);
                pool_c.push_back(sums[q]);
                pool_d.push_back(wd[pos[q]]);
            }
            vlen[c] = static_cast<i64>(pos.size());
        }
    }
    return out;
}

// One dimension's output: births, deaths, essential births, the statistics (simplices, apparent,
// columns, emergent, reduced, additions, entries, enumerators) and, when asked for, the cocycles of
// the finite bars then of the essential ones: their offsets (one more than the bars; [0] when not
// asked for, and in dimension 0) and their rows, (vertices, coefficient) each.
using DimResult = std::tuple<Array<double>, Array<double>, Array<double>, Array<i64>, Array<i64>, Array<i64>>;

// The options of rips_barcode: the largest simplex dimension, the prime, whether the dense distance
// matrix is kept, the threads (0: OMP_NUM_THREADS or every core), the number of k-simplices from
// which a dimension is assembled in parallel, and whether representative cocycles are returned.
struct Options {
    i64 max_dim = 2;
    i64 p = 2;
    bool dense = true;
    int n_threads = 0;
    i64 parallel_min = 50000;
    bool cocycles = false;
};

// Refuse a graph that is not the symmetric, sorted neighbour lists of rips_graph.
void check_graph(i64 n, const i64* indptr, std::size_t nptr, const i64* nbr, const double* length, std::size_t nnbr,
                 std::size_t nlen) {
    if (n < 1) throw std::invalid_argument("rips_barcode: n must be >= 1");
    if (nptr != static_cast<std::size_t>(n + 1)) throw std::invalid_argument("rips_barcode: indptr must have n + 1 entries");
    if (indptr[0] != 0) throw std::invalid_argument("rips_barcode: indptr[0] must be 0");
    for (i64 v = 0; v < n; ++v)
        if (indptr[v + 1] < indptr[v]) throw std::invalid_argument("rips_barcode: indptr must be non-decreasing");
    if (static_cast<std::size_t>(indptr[n]) != nnbr || nlen != nnbr)
        throw std::invalid_argument("rips_barcode: indptr[n], neighbours and lengths disagree in size");
    for (i64 v = 0; v < n; ++v) {
        for (i64 e = indptr[v]; e < indptr[v + 1]; ++e) {
            const i64 u = nbr[e];
            if (u < 0 || u >= n || u == v) throw std::invalid_argument("rips_barcode: a neighbour outside 0 .. n - 1");
            if (e > indptr[v] && nbr[e - 1] <= u)
                throw std::invalid_argument("rips_barcode: neighbour lists must be strictly decreasing");
            if (std::isnan(length[e])) throw std::invalid_argument("rips_barcode: a length is NaN");
        }
    }
    for (i64 v = 0; v < n; ++v) {  // symmetric, with equal lengths (lists sorted: binary search)
        for (i64 e = indptr[v]; e < indptr[v + 1]; ++e) {
            const i64 u = nbr[e];
            i64 lo = indptr[u], hi = indptr[u + 1];
            while (lo < hi) {
                const i64 mid = (lo + hi) >> 1;
                if (nbr[mid] > v)
                    lo = mid + 1;
                else
                    hi = mid;
            }
            if (lo == indptr[u + 1] || nbr[lo] != v || !(length[lo] == length[e]))
                throw std::invalid_argument("rips_barcode: the neighbour lists are not symmetric");
        }
    }
}

// The barcode of the Rips filtration of the graph in dimensions 0 .. max_dim − 1, in diameters: births,
// deaths and essential births per dimension (in dimension 0 the vertices are born at vertex_births,
// inf for a vertex not in the complex; an edge's length is at least its vertices' births), with the
// statistics of the reduction above dimension 0 and, with options.cocycles, a representative cocycle
// of each bar of dimension >= 1 (implicit_rips_cocycles.hpp).
// Thesis: Definition 2.11 (Rips), Theorem 2.39 / Algorithm 2 (the pairs, by the dual reduction),
// Definitions 4.30–4.33 and Theorem 4.42 (apparent pairs as a discrete gradient).
std::vector<DimResult> rips_barcode(i64 n, In<i64, nb::ndim<1>> indptr, In<i64, nb::ndim<1>> neighbours,
                                    In<double, nb::ndim<1>> lengths, In<double, nb::ndim<1>> vertex_births,
                                    const Options& options) {
    const i64 max_dim = options.max_dim, p = options.p, parallel_min = options.parallel_min;
    const bool dense = options.dense;
    check_graph(n, indptr.data(), indptr.shape(0), neighbours.data(), lengths.data(), neighbours.shape(0),
                lengths.shape(0));
    if (vertex_births.shape(0) != static_cast<std::size_t>(n))
        throw std::invalid_argument("rips_barcode: vertex_births must have one entry per vertex");
    for (i64 v = 0; v < n; ++v)
        if (!(vertex_births.data()[v] >= 0.0)) throw std::invalid_argument("rips_barcode: a vertex birth is negative or NaN");
    if (max_dim < 1 || max_dim > n + 1) throw std::invalid_argument("rips_barcode: max_dim must be in 1 .. n + 1");
    if (p < 2 || p >= (i64(1) << 31)) throw std::invalid_argument("rips_barcode: p must be a prime below 2^31");
    if (dense && n > 46340) throw std::invalid_argument("rips_barcode: too many points for a dense matrix");
    const int threads = thread_count(options.n_threads);
    std::vector<DimOut> dims(static_cast<std::size_t>(max_dim));
    {
        nb::gil_scoped_release release;
        Graph g;
        g.n = n;
        g.indptr = indptr.data();
        g.nbr = neighbours.data();
        g.length = lengths.data();
        binomials(g, std::max(n + 1, max_dim + 2), max_dim + 1);
        prepare(g, dense);
        i64 maxdeg = 0;
        for (i64 v = 0; v < n; ++v) maxdeg = std::max(maxdeg, g.degree(v));
        // ---- H0: union–find
        std::vector<double> ed;
        std::vector<i64> ei;
        edges_by_index(g, ed, ei);
        std::vector<char> positive;
        h0(n, vertex_births.data(), ed, ei, dims[0], positive);
        // ---- dimensions 1 .. max_dim − 1: cohomology with clearing, apparent and emergent pairs
        Blocks from, all;  // the candidates of H1 (the positive edges); every (k − 1)-simplex, to build the k-simplices
        from.parts.emplace_back();
        if (max_dim > 2) all.parts.emplace_back();
        for (std::size_t e = 0; e < ei.size(); ++e) {
            if (positive[e]) from.parts[0].push_back({ed[e], ei[e]});
            if (max_dim > 2) all.parts[0].push_back({ed[e], ei[e]});
        }
        std::vector<double>().swap(ed);
        std::vector<i64>().swap(ei);
        Table cleared(0), uppers(0);
        for (i64 k = 1; k < max_dim; ++k) {
            // the k-simplices are kept to build dimension k + 1, unless that is the top dimension and at least
            // 3: it is built from the (k − 1)-simplices kept in all, two levels up (the top dimension's facets
            // are the longest list, and it is only walked once)
            const bool next = k + 1 < max_dim;
            const bool two = k >= 3 && !next;
            const bool keep = next && !(k + 2 == max_dim && k >= 2);
            const Assembly step = k == 1 ? Assembly{1, from, 0, false, next, cleared, uppers}
                                         : Assembly{k, all, two ? 2 : 1, keep, next, cleared, uppers};
            std::vector<Assembled> parts = assemble(g, step, maxdeg, threads, parallel_min);
            if (k >= 2 && (keep || !next)) {
                all.parts.clear();
                if (keep)
                    for (Assembled& a : parts) all.parts.push_back(std::move(a.all));
            }
            i64 ncand = 0, napp = 0;
            std::size_t ncol = 0, nup = 0;
            for (const Assembled& a : parts) {
                ncand += a.candidates;
                napp += a.apparent;
                ncol += a.columns.size();
                nup += a.uppers.size();
            }
            uppers = Table(static_cast<i64>(nup));  // the uppers of this dimension's pairs, cleared from the next
            for (Assembled& a : parts) {
                for (i64 t : a.uppers) uppers.keys[static_cast<std::size_t>(uppers.slot(t))] = t;
                std::vector<i64>().swap(a.uppers);
            }
            std::vector<Column> cols;
            cols.reserve(ncol);
            for (Assembled& a : parts) {
                cols.insert(cols.end(), a.columns.begin(), a.columns.end());
                std::vector<Column>().swap(a.columns);
            }
            // latest first: diameter down, index up
            std::sort(cols.begin(), cols.end(),
                      [](const Column& a, const Column& b) { return a.d > b.d || (a.d == b.d && a.idx < b.idx); });
            Reduced red = reduce(g, k, cols, p, options.cocycles);
            DimOut& out = dims[static_cast<std::size_t>(k)];
            out.births = std::move(red.births);
            out.deaths = std::move(red.deaths);
            out.ess = std::move(red.ess);
            if (options.cocycles) {  // the finite bars' cocycles, then the essential ones'
                out.cocycles = std::move(red.finite);
                extend(out.cocycles, red.essential);
            }
            out.stats = {ncand, napp, static_cast<i64>(cols.size()), red.emergent, red.worked, red.additions, red.read,
                         red.most};
            cleared = std::move(red.pivots);
        }
    }
    std::vector<DimResult> result;
    for (std::size_t k = 0; k < dims.size(); ++k) {
        DimOut& d = dims[k];
        const std::size_t nrows = d.cocycles.rows.size() / (k + 2);
        result.emplace_back(to_numpy(std::move(d.births)), to_numpy(std::move(d.deaths)), to_numpy(std::move(d.ess)),
                            to_numpy(std::move(d.stats)), to_numpy(std::move(d.cocycles.offsets)),
                            to_numpy(std::move(d.cocycles.rows), {nrows, k + 2}));
    }
    return result;
}

}  // namespace rips
}  // namespace thesis

NB_MODULE(implicit_rips, m) {
    namespace nb = nanobind;
    m.doc() = "The implicit Vietoris–Rips persistence engine (thesis Definition 2.11, Algorithm 2, §4.2), "
              "with representative cocycles on request.";
    m.def("neighbour_lists", &thesis::rips::neighbour_lists, nb::arg("n"), nb::arg("edges"), nb::arg("lengths"),
          "Symmetric neighbour lists (indptr, neighbours, lengths) of the edges, each list by decreasing vertex.");
    nb::class_<thesis::rips::Options>(m, "Options", "The options of rips_barcode.")
        .def(nb::init<>())
        .def_rw("max_dim", &thesis::rips::Options::max_dim)
        .def_rw("p", &thesis::rips::Options::p)
        .def_rw("dense", &thesis::rips::Options::dense)
        .def_rw("n_threads", &thesis::rips::Options::n_threads)
        .def_rw("parallel_min", &thesis::rips::Options::parallel_min)
        .def_rw("cocycles", &thesis::rips::Options::cocycles);
    m.def("rips_barcode", &thesis::rips::rips_barcode, nb::arg("n"), nb::arg("indptr"), nb::arg("neighbours"),
          nb::arg("lengths"), nb::arg("vertex_births"), nb::arg("options"),
          "Per dimension 0 .. max_dim - 1: (births, deaths, essential births, statistics, cocycle offsets, "
          "cocycle rows), in diameters.");
}
