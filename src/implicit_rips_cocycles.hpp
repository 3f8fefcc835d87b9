// Representative cocycles of the implicit Rips engine: the reduction chain of each coboundary column
// that gives a persistence pair, listed as ripser.py lists it.
//
// The coboundary columns of dimension k are reduced latest first, so the chain V_s of the column of a
// k-simplex s is s (coefficient 1) plus multiples of later simplices, those whose coboundaries (or the
// columns owning a pivot) were added to it.  Its coboundary δV_s is the reduced column: zero for an
// essential class, else with its earliest non-zero entry at the pair's (k + 1)-simplex τ.  So V_s,
// restricted to the simplices of value <= t, is a cocycle of the complex at t for every t from the
// birth (s's value) to just before the death (τ's value), and its class there is not zero.  Only the
// pairs of positive length are asked for: they never come from an emergent or an apparent pair (both
// have zero length), so their chains are always the working chains of a reduced column.
// Used by implicit_rips.cpp only.
#pragma once

#include <algorithm>
#include <vector>

#include "implicit_rips_graph.hpp"

namespace thesis {
namespace rips {

// The added entries of one working chain, not yet summed: simplex indices, coefficients mod p and
// diameters, size of each.
struct ChainView {
    const i64* keys;
    const i64* coefs;
    const double* diams;
    i64 size;
};

// The cocycles of one dimension k, one after the other: cocycle c is rows offsets[c] .. offsets[c + 1] − 1,
// each row the k + 1 vertices of a simplex (decreasing) then its coefficient in 1 .. p − 1.
struct CocycleList {
    std::vector<i64> offsets{0};
    std::vector<i64> rows;
};

// Append the chain s + Σ chain (the k-simplex s of diameter ds with coefficient 1) summed mod p, zero
// entries dropped, its simplices in filtration order (diameter up, index down), as ripser.py lists a
// representative cocycle.
// Thesis: Theorem 2.39 (the columns of V with M_p V reduced), on the coboundary side (§2.3.5).
inline void append_cocycle(const Graph& g, i64 k, i64 p, i64 s, double ds, const ChainView& chain, CocycleList& out) {
    struct Entry {
        double d;
        i64 idx, c;
    };
    std::vector<Entry> entries;
    entries.reserve(static_cast<std::size_t>(chain.size + 1));
    entries.push_back({ds, s, 1});
    for (i64 q = 0; q < chain.size; ++q) entries.push_back({chain.diams[q], chain.keys[q], chain.coefs[q]});
    // a simplex has one diameter: sorting by (diameter up, index down) brings its entries together
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.d < b.d || (a.d == b.d && a.idx > b.idx); });
    std::vector<i64> verts(static_cast<std::size_t>(k + 1));
    std::size_t i = 0;
    while (i < entries.size()) {
        const i64 idx = entries[i].idx;
        i64 c = 0;
        for (; i < entries.size() && entries[i].idx == idx; ++i) c = (c + entries[i].c) % p;
        if (c == 0) continue;
        vertices(g, idx, k, verts.data());
        out.rows.insert(out.rows.end(), verts.begin(), verts.end());
        out.rows.push_back(c);
    }
    out.offsets.push_back(static_cast<i64>(out.rows.size()) / (k + 2));
}

// Append the cocycles of more after those of out (the essential bars' after the finite ones').
// Thesis: Theorem 2.39 (the finite P-intervals, then the infinite ones).
inline void extend(CocycleList& out, const CocycleList& more) {
    const i64 before = out.offsets.back();
    for (std::size_t c = 1; c < more.offsets.size(); ++c) out.offsets.push_back(before + more.offsets[c]);
    out.rows.insert(out.rows.end(), more.rows.begin(), more.rows.end());
}

}  // namespace rips
}  // namespace thesis
