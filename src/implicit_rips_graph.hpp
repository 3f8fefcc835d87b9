// The neighbour graph of a Rips filtration and the simplices it determines, for the implicit engine.
//
// A Rips complex is a flag complex: a simplex is its vertices, its value the longest edge.  Only the
// graph (diameter <= 2 eps) is stored, as neighbour lists sorted by decreasing vertex (nbr, length)
// and the same lists sorted by (distance up, vertex down) (dnbr, dlen); a k-simplex {v_k > ... > v_0}
// is the integer C(v_0, 1) + ... + C(v_k, k + 1) (the combinatorial number system), decoded by binary
// search in a table of binomials.  Index arithmetic wraps modulo 2^64 as the numba original's int64
// did (the Python layer refuses indices that could overflow; the table's unused corners may).
// Used by implicit_rips.cpp only.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace thesis {
namespace rips {

using i64 = std::int64_t;
using u64 = std::uint64_t;

constexpr double kInf = std::numeric_limits<double>::infinity();

// a + b and a - b modulo 2^64 (numba's int64 arithmetic, without C++'s signed-overflow UB).
inline i64 wadd(i64 a, i64 b) { return static_cast<i64>(static_cast<u64>(a) + static_cast<u64>(b)); }
inline i64 wsub(i64 a, i64 b) { return static_cast<i64>(static_cast<u64>(a) - static_cast<u64>(b)); }

// An edge of the hash of lengths: key u · n + v (u > v), −1 for an empty slot.
struct EdgeSlot {
    i64 key;
    double length;
};

// The validated graph, its distance-sorted lists, the lengths for constant-time lookups (a dense
// matrix, or a hash of the edges when the matrix would be mostly empty) and the binomials.
struct Graph {
    i64 n = 0;
    const i64* indptr = nullptr;
    const i64* nbr = nullptr;
    const double* length = nullptr;
    std::vector<i64> dnbr;
    std::vector<double> dlen;
    std::vector<double> D;  // n * n, inf where there is no edge; empty when not dense
    bool dense = false;
    std::vector<EdgeSlot> H;  // open addressing, load at most 1/2; empty when dense
    u64 hmask = 0;
    int hshift = 60;
    std::vector<i64> B;  // B[v * bw + k] = C(v, k)
    i64 bw = 0;

    i64 binom(i64 v, i64 k) const { return B[static_cast<std::size_t>(v * bw + k)]; }
    i64 degree(i64 v) const { return indptr[v + 1] - indptr[v]; }

    // The hash slot of key (u · n + v, u > v): where it is, or the empty slot where it would go.
    u64 hslot(i64 key) const {
        u64 h = (static_cast<u64>(key) * 0x9E3779B97F4A7C15ULL) >> hshift;
        while (H[h].key != -1 && H[h].key != key) h = (h + 1) & hmask;
        return h;
    }

    // Distance of u and v: from the dense matrix or the hash of the edges; inf if there is no edge.
    // Thesis: Definition 2.11 (the edge lengths of the Rips graph).
    double dist(i64 u, i64 v) const {
        if (dense) return D[static_cast<std::size_t>(u * n + v)];
        const EdgeSlot& e = H[hslot(u > v ? u * n + v : v * n + u)];
        return e.key == -1 ? kInf : e.length;
    }
};

// B[v, k] = C(v, k) for 0 <= v < rows, 0 <= k <= kmax (Pascal's rule, wrapping as numba's int64).
// Thesis: §2.3.5 (the simplices of the filtration indexed by the combinatorial number system).
inline void binomials(Graph& g, i64 rows, i64 kmax) {
    g.bw = kmax + 1;
    g.B.assign(static_cast<std::size_t>(rows * g.bw), 0);
    for (i64 v = 0; v < rows; ++v) {
        g.B[static_cast<std::size_t>(v * g.bw)] = 1;
        const i64 top = v < kmax ? v : kmax;
        for (i64 k = 1; k <= top; ++k)
            g.B[static_cast<std::size_t>(v * g.bw + k)] =
                wadd(g.B[static_cast<std::size_t>((v - 1) * g.bw + k - 1)],
                     k <= v - 1 ? g.B[static_cast<std::size_t>((v - 1) * g.bw + k)] : 0);
    }
}

// The largest v <= top with C(v, kk) <= idx (the top vertex of a simplex of kk vertices and index idx,
// when it is at most top): binary search down to a range of 8, then a scan down (the range is small
// for the lower vertices of a high-dimensional simplex of a small complex).
// Thesis: §2.3.5 (a simplex read back from its index).
inline i64 top_vertex(const Graph& g, i64 idx, i64 kk, i64 top) {
    i64 lo = kk - 1, hi = top;  // C(lo, kk) = 0 <= idx: the vertex is in lo .. hi
    while (hi - lo > 8) {
        const i64 mid = (lo + hi + 1) >> 1;
        if (g.binom(mid, kk) <= idx)
            lo = mid;
        else
            hi = mid - 1;
    }
    while (g.binom(hi, kk) > idx) --hi;
    return hi;
}

// The vertices of the k-simplex idx, all at most top, decreasing, into out[0..k].
// Thesis: §2.3.5 (a simplex read back from its index).
inline void vertices(const Graph& g, i64 idx, i64 k, i64* out, i64 top) {
    for (i64 r = 0; r <= k; ++r) {
        out[r] = top_vertex(g, idx, k + 1 - r, top);
        idx = wsub(idx, g.binom(out[r], k + 1 - r));
        top = out[r] - 1;
    }
}

// The vertices of the k-simplex idx (below n), decreasing, into out[0..k].
// Thesis: §2.3.5 (a simplex read back from its index).
inline void vertices(const Graph& g, i64 idx, i64 k, i64* out) { vertices(g, idx, k, out, g.n - 1); }

// First position in the increasing arr[lo..hi) with a value > x.
inline i64 upper(const double* arr, i64 lo, i64 hi, double x) {
    while (lo < hi) {
        const i64 mid = (lo + hi) >> 1;
        if (arr[mid] <= x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

// The buffers an enumeration of cofaces writes into: cur, one list position per vertex of the simplex
// (scratch), and per coface found its diameter, index and new vertex (d, index, j: room for as many
// cofaces as the simplex's vertex of least degree has neighbours, or for one when only the first is
// asked for).
struct CofaceBuffers {
    i64* cur;
    double* d;
    i64* index;
    i64* j;
};

// Enumerate the cofaces s ∪ {j} of the k-simplex s (vertices verts, decreasing), j decreasing: each
// coface's diameter, index and new vertex j into out, returning their number.  With first_equal it
// stops at the first coface of diameter diam (the earliest coface when one has s's diameter) and
// returns 1 (0 when there is none); with above_only only cofaces whose new vertex is above s's are
// listed (each (k+1)-simplex from exactly one facet).
// Thesis: Definition 2.11 (a coface of a flag simplex is a common neighbour), §2.3.5 (coboundary).
inline i64 cofaces(const Graph& g, const i64* verts, i64 k, i64 idx, double diam, const CofaceBuffers& out,
                   bool first_equal, bool above_only) {
    i64* cur = out.cur;
    double* out_d = out.d;
    i64* out_i = out.index;
    i64* out_j = out.j;
    const i64* indptr = g.indptr;
    const i64* nbr = g.nbr;
    const double* length = g.length;
    i64 base = 0;
    for (i64 i = 0; i <= k; ++i) {
        cur[i] = indptr[verts[i]];
        if (indptr[verts[i] + 1] - indptr[verts[i]] < indptr[verts[base] + 1] - indptr[verts[base]]) base = i;
    }
    const i64 vb = verts[base];
    i64 idx_above = 0;
    i64 idx_below = idx;
    i64 m = 0;
    i64 count = 0;
    for (i64 e = indptr[vb]; e < indptr[vb + 1]; ++e) {
        const i64 j = nbr[e];
        if (above_only && j < verts[0]) break;
        while (m <= k && verts[m] > j) {
            idx_below = wsub(idx_below, g.binom(verts[m], k + 1 - m));
            idx_above = wadd(idx_above, g.binom(verts[m], k + 2 - m));
            ++m;
        }
        double dmax = length[e] > diam ? length[e] : diam;
        bool ok = true;
        for (i64 i = 0; i <= k; ++i) {
            if (i == base) continue;
            i64 c = cur[i];
            const i64 end = indptr[verts[i] + 1];
            while (c < end && nbr[c] > j) ++c;
            cur[i] = c;
            if (c == end || nbr[c] != j) {
                ok = false;
                break;
            }
            if (length[c] > dmax) dmax = length[c];
        }
        if (!ok) continue;
        if (first_equal) {
            if (dmax == diam) {
                out_d[0] = dmax;
                out_i[0] = wadd(wadd(idx_above, g.binom(j, k + 2 - m)), idx_below);
                out_j[0] = j;
                return 1;
            }
            continue;
        }
        out_d[count] = dmax;
        out_i[count] = wadd(wadd(idx_above, g.binom(j, k + 2 - m)), idx_below);
        out_j[count] = j;
        ++count;
    }
    return count;
}

// A coface found: its index, m = #vertices of s above the new vertex, and that vertex j (−1 when
// unknown); index −1 when there is none.
struct Coface {
    i64 index;
    i64 m;
    i64 j;
};

// (index of s ∪ {j}, m, j) for the k-simplex s = idx; (−1, 0, −1) when j < 0.
inline Coface with_vertex(const Graph& g, const i64* verts, i64 k, i64 idx, i64 j) {
    if (j < 0) return {-1, 0, -1};
    i64 idx_above = 0;
    i64 idx_below = idx;
    i64 m = 0;
    while (m <= k && verts[m] > j) {
        idx_below = wsub(idx_below, g.binom(verts[m], k + 1 - m));
        idx_above = wadd(idx_above, g.binom(verts[m], k + 2 - m));
        ++m;
    }
    return {wadd(wadd(idx_above, g.binom(j, k + 2 - m)), idx_below), m, j};
}

// The largest j within diam of each of the k + 1 vertices verts in the dense matrix, −1 if none
// (D[v, v] = inf: the vertices themselves never match).
inline i64 dense_first(const Graph& g, const i64* verts, i64 k, double diam) {
    for (i64 j = g.n - 1; j >= 0; --j) {
        bool ok = true;
        for (i64 i = 0; i <= k; ++i) {
            if (g.D[static_cast<std::size_t>(verts[i] * g.n + j)] > diam) {
                ok = false;
                break;
            }
        }
        if (ok) return j;
    }
    return -1;
}

// The earliest coface of the k-simplex s if it has s's diameter (index −1 otherwise), its m and its
// new vertex j (−1 when not known).  The cofaces of s's diameter are s ∪ {j} for the j within diam of
// every vertex; the earliest has the largest j.  When one vertex has few neighbours that close they
// are read from its distance-sorted list and checked; otherwise the coboundary is scanned with j
// decreasing up to the first hit (with a dense matrix, a scan of its columns j = n − 1, n − 2, ...),
// written into out (room for one coface).
// Thesis: Definition 4.30 (the earliest coface of a zero apparent pair), Theorem 4.42's idea.
inline Coface zero_pivot_cofacet(const Graph& g, const i64* verts, i64 k, i64 idx, double diam,
                                 const CofaceBuffers& out) {
    const i64* indptr = g.indptr;
    const double* dlen = g.dlen.data();
    if (g.dense) {  // every vertex has more than 1/8 of its neighbours within diam: scan D
        bool wide = true;
        for (i64 i = 0; i <= k; ++i) {
            const i64 v = verts[i];
            const i64 deg = indptr[v + 1] - indptr[v];
            if (deg == 0 || dlen[indptr[v] + deg / 8] > diam) {
                wide = false;
                break;
            }
        }
        if (wide) return with_vertex(g, verts, k, idx, dense_first(g, verts, k, diam));
    }
    i64 best = -1;
    i64 bcount = i64(1) << 62;
    for (i64 i = 0; i <= k; ++i) {
        const i64 v = verts[i];
        const i64 c = upper(dlen, indptr[v], indptr[v + 1], diam) - indptr[v];
        if (c < bcount) {
            bcount = c;
            best = i;
        }
    }
    i64 jmax = -1;
    if (8 * bcount > indptr[verts[best] + 1] - indptr[verts[best]]) {
        if (g.dense) return with_vertex(g, verts, k, idx, dense_first(g, verts, k, diam));
        if (cofaces(g, verts, k, idx, diam, out, true, false)) return with_vertex(g, verts, k, idx, out.j[0]);
        return {-1, 0, -1};
    }
    const i64 vb = verts[best];
    for (i64 e = indptr[vb]; e < indptr[vb] + bcount; ++e) {
        const i64 j = g.dnbr[static_cast<std::size_t>(e)];
        if (j <= jmax) continue;
        bool ok = true;
        for (i64 i = 0; i <= k; ++i) {
            if (i != best && g.dist(verts[i], j) > diam) {
                ok = false;
                break;
            }
        }
        if (ok) jmax = j;
    }
    return with_vertex(g, verts, k, idx, jmax);
}

// The latest facet of the k1-simplex tau (k1 >= 2) of diameter diam if it has tau's diameter (−1
// otherwise): tau with w[r] omitted for the least r that avoids an edge of length diam.  When an edge
// of w[1..k1] has length diam, r = 0 (checked first, up to the first such edge); otherwise every such
// edge meets w[0], so r = 1 unless the only one is {w[0], w[1]}, and then r = 2.  With known the
// vertices of tau are already in w (decreasing); otherwise they are decoded.
// Thesis: Definition 4.30 (the latest facet of a zero apparent pair).
inline i64 zero_pivot_facet(const Graph& g, i64 tau, i64 k1, double diam, i64* w, bool known) {
    if (!known) vertices(g, tau, k1, w);
    i64 r = -1;
    for (i64 a = 1; a <= k1 && r == -1; ++a)
        for (i64 b = a + 1; b <= k1; ++b)
            if (g.dist(w[a], w[b]) == diam) {
                r = 0;
                break;
            }
    if (r == -1) {
        for (i64 b = 1; b <= k1 && r == -1; ++b)
            if (g.dist(w[0], w[b]) == diam) r = b == 1 ? 2 : 1;
        if (r == 2)  // {w[0], w[1]} has length diam: r = 1 too if another edge at w[0] does
            for (i64 b = 2; b <= k1; ++b)
                if (g.dist(w[0], w[b]) == diam) {
                    r = 1;
                    break;
                }
    }
    if (r == -1) return -1;
    i64 idx = tau;  // omit w[r]: the vertices above it move down one binomial
    for (i64 q = 0; q < r; ++q) idx = wadd(wsub(idx, g.binom(w[q], k1 + 1 - q)), g.binom(w[q], k1 - q));
    return wsub(idx, g.binom(w[r], k1 + 1 - r));
}

// An open-addressing hash table of non-negative int64 keys (−1: empty), capacity a power of two at
// least 2 size + 2.
struct Table {
    std::vector<i64> keys;
    std::unique_ptr<i64[]> vals;  // read only where keys are set: left uninitialised (as numba's np.empty)
    i64 mask = 0;

    explicit Table(i64 size) {
        i64 cap = 16;
        while (cap < 2 * size + 2) cap *= 2;
        keys.assign(static_cast<std::size_t>(cap), -1);
        vals.reset(new i64[static_cast<std::size_t>(cap)]);
        mask = cap - 1;
    }
    // The slot holding key, or the empty slot where it would go.
    i64 slot(i64 key) const {
        i64 h = static_cast<i64>((static_cast<u64>(key) * 0x9E3779B97F4A7C15ULL) >> 17) & mask;
        while (keys[static_cast<std::size_t>(h)] != -1 && keys[static_cast<std::size_t>(h)] != key) h = (h + 1) & mask;
        return h;
    }
    bool contains(i64 key) const { return keys[static_cast<std::size_t>(slot(key))] != -1; }
};

}  // namespace rips
}  // namespace thesis
