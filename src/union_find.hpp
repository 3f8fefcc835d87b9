// Union–find (disjoint sets) with path halving: the one find of the compiled kernels.
//
// Used by the elder rule of H0 (Definition 2.31, both persistence engines) and by the link check of
// pseudo-manifolds (§3.3).
#pragma once

#include <cstdint>

namespace thesis {

// The root of x in the forest parent, halving the path on the way.
// Thesis: §2.3.4 (H0 by the elder rule joins components as edges enter the filtration).
template <class Index>
inline Index find(Index* parent, Index x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

}  // namespace thesis
