// Partial pivoting, shared by the small dense solvers of the Čech and alpha constructions: the
// Gaussian elimination of the smallest enclosing ball (src/miniball.cpp) and the Gauss–Jordan inverse
// of the orthogonal sphere's system (src/predicate_filters.cpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>

namespace thesis {

// The row r in col..k-1 of the row-major matrix `mat` (row stride `stride`) with the largest
// |mat[r, col]| (the first on ties), and that magnitude.
// Thesis: §2.1.2 (the small linear systems of the Miniball Algorithm and of the orthogonal spheres).
inline std::pair<std::size_t, double> pivot_row(const double* mat, std::size_t stride, std::size_t col,
                                                std::size_t k) {
    std::size_t piv = col;
    double best = std::fabs(mat[col * stride + col]);
    for (std::size_t r = col + 1; r < k; ++r) {
        if (std::fabs(mat[r * stride + col]) > best) {
            best = std::fabs(mat[r * stride + col]);
            piv = r;
        }
    }
    return {piv, best};
}

}  // namespace thesis
