// The smallest enclosing balls of the Čech complex (thesis Definition 2.9, Theorem 2.10, §2.1.2 the
// Miniball Algorithm): the port of meb_radius_small and _solve_small (thesis_lib/complexes/miniball.py)
// and of _meb_radii (thesis_lib/complexes/cech.py).
//
// The smallest ball enclosing the few vertices of one simplex is the circumscribed ball, within the
// affine hull, of some subset of them, so its radius is the smallest such circumradius whose ball
// contains every vertex: a search over the 2^k subsets.
#include "arrays.hpp"
#include "geometry_arrays.hpp"
#include "pivot_row.hpp"

#include <cmath>
#include <limits>

namespace thesis {

namespace {

constexpr std::size_t kMaxPoints = 62;  // the subset search counts masks up to 2^k in an int64

// Gaussian elimination with partial pivoting on the leading k × k block of the row-major matrix a
// (row stride `stride`, the elimination works on the copy m) with right-hand side x (overwritten by
// the solution); false if singular (a pivot below 1e-13 of the block's largest entry).
// Thesis: §2.1.2 (the circumcentre's linear system in the Miniball Algorithm).
bool solve_small(const double* a, std::size_t stride, double* m, double* x, std::size_t k) {
    for (std::size_t i = 0; i < stride * stride; ++i) m[i] = a[i];
    double scale = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
            const double v = std::fabs(m[i * stride + j]);
            if (v > scale) scale = v;  // Python's max(scale, v): the first of equals
        }
    }
    if (scale == 0.0) return false;
    for (std::size_t col = 0; col < k; ++col) {
        const auto [piv, best] = pivot_row(m, stride, col, k);
        if (best <= 1e-13 * scale) return false;
        if (piv != col) {
            for (std::size_t j = 0; j < k; ++j) std::swap(m[col * stride + j], m[piv * stride + j]);
            std::swap(x[col], x[piv]);
        }
        for (std::size_t r = col + 1; r < k; ++r) {
            const double f = m[r * stride + col] / m[col * stride + col];
            for (std::size_t j = col; j < k; ++j) m[r * stride + j] -= f * m[col * stride + j];
            x[r] -= f * x[col];
        }
    }
    for (std::size_t col = k; col-- > 0;) {
        double s = x[col];
        for (std::size_t j = col + 1; j < k; ++j) s -= m[col * stride + j] * x[j];
        x[col] = s / m[col * stride + col];
    }
    return true;
}

// Scratch space of meb_radius for k points in R^dim.
struct MebWork {
    std::vector<double> gram, rhs, centre, m, x;
    std::vector<std::size_t> sub;
    MebWork(std::size_t k, std::size_t dim) : gram(k * k), rhs(k), centre(dim), m(k * k), x(k), sub(k) {}
};

// Radius of the smallest enclosing ball of the k points (rows of the row-major pts, k × dim), by
// subset search.  Thesis: Definition 2.9 / Theorem 2.10 (the ball realising the Čech value).
double meb_radius(const double* pts, std::size_t k, std::size_t dim, MebWork& w) {
    if (k == 1) return 0.0;
    const double inf = std::numeric_limits<double>::infinity();
    double best = inf;
    double scale = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < dim; ++j) {
            const double v = std::fabs(pts[i * dim + j] - pts[j]);
            if (v > scale) scale = v;
        }
    }
    const double slack = 1e-12 * scale * scale;
    const std::uint64_t end = std::uint64_t{1} << k;
    for (std::uint64_t mask = 1; mask < end; ++mask) {
        std::size_t size = 0;
        for (std::size_t i = 0; i < k; ++i) {
            if (mask >> i & 1) w.sub[size++] = i;
        }
        if (size == 1) continue;  // a single point encloses the others only if they coincide (radius 0 below)
        const double* p0 = pts + w.sub[0] * dim;
        for (std::size_t a = 0; a + 1 < size; ++a) {
            const double* pa = pts + w.sub[a + 1] * dim;
            double s = 0.0;
            for (std::size_t t = 0; t < dim; ++t) {
                const double da = pa[t] - p0[t];
                s += da * da;
            }
            w.rhs[a] = s;
            for (std::size_t b = 0; b + 1 < size; ++b) {
                const double* pb = pts + w.sub[b + 1] * dim;
                double g = 0.0;
                for (std::size_t t = 0; t < dim; ++t) g += (pa[t] - p0[t]) * (pb[t] - p0[t]);
                w.gram[a * k + b] = 2.0 * g;
            }
        }
        for (std::size_t i = 0; i < k; ++i) w.x[i] = w.rhs[i];
        if (!solve_small(w.gram.data(), k, w.m.data(), w.x.data(), size - 1)) continue;
        for (std::size_t t = 0; t < dim; ++t) {
            double c = p0[t];
            for (std::size_t a = 0; a + 1 < size; ++a) c += w.x[a] * (pts[w.sub[a + 1] * dim + t] - p0[t]);
            w.centre[t] = c;
        }
        double r2 = 0.0;
        for (std::size_t t = 0; t < dim; ++t) {
            const double dt = w.centre[t] - p0[t];
            r2 += dt * dt;
        }
        if (r2 >= best) continue;
        bool inside = true;
        for (std::size_t i = 0; i < k; ++i) {
            double d2 = 0.0;
            for (std::size_t t = 0; t < dim; ++t) {
                const double dt = pts[i * dim + t] - w.centre[t];
                d2 += dt * dt;
            }
            if (d2 > r2 + slack + 1e-12 * r2) {
                inside = false;
                break;
            }
        }
        if (inside) best = r2;
    }
    if (best == inf) return 0.0;  // all points coincide
    return std::sqrt(best);
}

void check_count(std::size_t k) {
    if (k > kMaxPoints) {
        throw std::invalid_argument("the subset search takes at most " + std::to_string(kMaxPoints) +
                                    " points, got " + std::to_string(k));
    }
}

}  // namespace

// Radius of the smallest enclosing ball of a few points (rows of pts), by subset search.
// Thesis: Definition 2.9 / Theorem 2.10 (the ball realising the Čech value of a simplex).
double meb_radius_small(In<double, nb::ndim<2>> pts) {
    const std::size_t k = pts.shape(0), dim = pts.shape(1);
    check_count(k);
    nb::gil_scoped_release release;
    MebWork w(k, dim);
    return meb_radius(pts.data(), k, dim, w);
}

// The enclosing radius of every row of simplices (vertex indices into points).
// Thesis: Definition 2.9 (the value of a simplex of the Čech filtration C(X, ε)).
Array<double> meb_radii(In<double, nb::ndim<2>> points, In<std::int64_t, nb::ndim<2>> simplices) {
    const std::size_t n = points.shape(0), dim = points.shape(1);
    const std::size_t m = simplices.shape(0), k = simplices.shape(1);
    check_count(k);
    check_indices(simplices.data(), simplices.size(), n, "simplices");
    std::vector<double> out(m);
    {
        nb::gil_scoped_release release;
        MebWork w(k, dim);
        std::vector<double> buf(k * dim);
        const double* P = points.data();
        const std::int64_t* S = simplices.data();
        for (std::size_t r = 0; r < m; ++r) {
            for (std::size_t i = 0; i < k; ++i)
                for (std::size_t t = 0; t < dim; ++t) buf[i * dim + t] = P[S[r * k + i] * dim + t];
            out[r] = meb_radius(buf.data(), k, dim, w);
        }
    }
    return to_numpy(std::move(out));
}

}  // namespace thesis

NB_MODULE(miniball, m) {
    namespace nb = nanobind;
    m.doc() = "Smallest enclosing balls of a few points, the Čech complex's values (thesis Definition 2.9, §2.1.2).";
    m.def("meb_radius_small", &thesis::meb_radius_small, nb::arg("pts"));
    m.def("meb_radii", &thesis::meb_radii, nb::arg("points"), nb::arg("simplices"));
}
