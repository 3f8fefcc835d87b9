// Floating-point filters of the robust predicates of the Delaunay and alpha complexes (thesis §2.1.2,
// Definitions 2.13 and 2.14): the port of thesis_lib/complexes/filters.py.
//
// Each filter computes, row by row, a determinant by Laplace expansion over subsets of rows together
// with its permanent (the same expansion on absolute values), and returns the sign where the value
// exceeds the proven rounding-error bound (e·k + (k² + 2k)·u)·1.01·permanent (e the entries' own
// relative error), 0 where it does not: those rows go to exact arithmetic.  The bounds are only valid
// for these operations in this order (the build contracts no a*b+c into an FMA).
#include "arrays.hpp"
#include "geometry_arrays.hpp"
#include "pivot_row.hpp"

#include <nanobind/stl/tuple.h>

#include <cmath>
#include <limits>
#include <tuple>

namespace thesis {

namespace {

constexpr double kU = 1.0 / 9007199254740992.0;  // 2^-53, the unit roundoff of float64
constexpr double kTiny = 1e-290;
constexpr std::size_t kMaxOrder = 30;  // the subset programme holds 2^k doubles

// Determinant and permanent of the k × k row-major matrices mat and mag (|entries|) by the subset
// dynamic programme: dbuf[mask] is the determinant of the rows in mask and the first popcount(mask)
// columns, expanded along its last column (rows in ascending order, as the numba original).
// Thesis: §2.1.2 (the filtered predicates).
std::pair<double, double> det_perm(const double* mat, const double* mag, std::size_t k, double* dbuf,
                                   double* pbuf) {
    const std::uint64_t end = std::uint64_t{1} << k;
    for (std::uint64_t mask = 1; mask < end; ++mask) {
        const int c = __builtin_popcountll(mask);
        const std::size_t j = static_cast<std::size_t>(c - 1);
        if (c == 1) {
            const std::size_t i = static_cast<std::size_t>(__builtin_ctzll(mask));
            dbuf[mask] = mat[i * k];
            pbuf[mask] = mag[i * k];
            continue;
        }
        double acc = 0.0;
        double pacc = 0.0;
        std::size_t pos = 0;
        for (std::uint64_t rest = mask; rest; rest &= rest - 1) {  // the rows of mask, ascending
            const std::size_t i = static_cast<std::size_t>(__builtin_ctzll(rest));
            const std::uint64_t sub = mask & ~(std::uint64_t{1} << i);
            double term = mat[i * k + j] * dbuf[sub];
            if ((pos + j) % 2) term = -term;
            acc += term;
            pacc += mag[i * k + j] * pbuf[sub];
            ++pos;
        }
        dbuf[mask] = acc;
        pbuf[mask] = pacc;
    }
    return {dbuf[end - 1], pbuf[end - 1]};
}

// The certain sign of det (0 if within the error bound of a k × k expansion with entry error e).
// Thesis: §2.1.2 (the filtered predicates).
std::int8_t signed_of(double det, double perm, std::size_t k, double entry_error) {
    const double kk = static_cast<double>(k);
    const double ops = static_cast<double>(k * k + 2 * k);
    const double bound = (entry_error * kk + ops * kU) * 1.01 * perm + kTiny;
    if (det > bound) return 1;
    if (det < -bound) return -1;
    return 0;
}

// Workspace of the subset programme for k × k determinants.
struct DetWork {
    std::vector<double> mat, mag, dbuf, pbuf;
    explicit DetWork(std::size_t k)
        : mat(k * k), mag(k * k), dbuf(std::size_t{1} << k), pbuf(std::size_t{1} << k) {}
};

void check_order(std::size_t k) {
    if (k < 1 || k > kMaxOrder) {
        throw std::invalid_argument("the filters take determinants of order 1 to " + std::to_string(kMaxOrder) +
                                    ", got " + std::to_string(k));
    }
}

void check_points(const In<double, nb::ndim<2>>& points, const In<std::int64_t, nb::ndim<2>>& simplices,
                  std::size_t width) {
    check_size(simplices.shape(1), width, "simplices: columns (the dimension + 1)");
    check_indices(simplices.data(), simplices.size(), points.shape(0), "simplices");
}

// Orientation signs of the rows (the work of orient_filter, GIL released by the caller).
void orient_rows(const double* P, std::size_t d, const std::int64_t* S, std::size_t m, std::int8_t* out) {
    DetWork w(d);
    for (std::size_t r = 0; r < m; ++r) {
        const std::int64_t* row = S + r * (d + 1);
        const double* o = P + row[0] * d;
        for (std::size_t i = 0; i < d; ++i) {
            const double* v = P + row[i + 1] * d;
            for (std::size_t t = 0; t < d; ++t) {
                const double x = v[t] - o[t];
                w.mat[i * d + t] = x;
                w.mag[i * d + t] = std::fabs(x);
            }
        }
        const auto [det, perm] = det_perm(w.mat.data(), w.mag.data(), d, w.dbuf.data(), w.pbuf.data());
        out[r] = signed_of(det, perm, d, kU);
    }
}

// Power-test signs of the rows (the work of insphere_filter, GIL released by the caller).
void insphere_rows(const double* P, const double* W, std::size_t d, const std::int64_t* S, const std::int64_t* Y,
                   std::size_t m, std::int8_t* out) {
    const std::size_t k = d + 1;
    DetWork w(k);
    const double entry_error = static_cast<double>(d + 4) * kU;
    for (std::size_t r = 0; r < m; ++r) {
        const std::int64_t q = Y[r];
        const double* xq = P + q * d;
        for (std::size_t i = 0; i < k; ++i) {
            const std::int64_t v = S[r * k + i];
            const double* xv = P + v * d;
            double sq = 0.0;
            for (std::size_t t = 0; t < d; ++t) {
                const double x = xv[t] - xq[t];
                w.mat[i * k + t] = x;
                w.mag[i * k + t] = std::fabs(x);
                sq += x * x;
            }
            w.mat[i * k + d] = sq - (W[v] - W[q]);
            w.mag[i * k + d] = sq + std::fabs(W[v]) + std::fabs(W[q]);
        }
        const auto [det, perm] = det_perm(w.mat.data(), w.mag.data(), k, w.dbuf.data(), w.pbuf.data());
        out[r] = signed_of(det, perm, k, entry_error);
    }
}

}  // namespace

// Certain signs of det[x_i − x_0] (0 where undecided) for the rows of simplices (m, d + 1).
// Thesis: §2.1.2 (orientation predicate of the Delaunay triangulation, Definition 2.13).
Array<std::int8_t> orient_filter(In<double, nb::ndim<2>> points, In<std::int64_t, nb::ndim<2>> simplices) {
    const std::size_t d = points.shape(1), m = simplices.shape(0);
    check_order(d);
    check_points(points, simplices, d + 1);
    std::vector<std::int8_t> out(m, 0);
    {
        nb::gil_scoped_release release;
        orient_rows(points.data(), d, simplices.data(), m, out.data());
    }
    return to_numpy(std::move(out));
}

// Certain signs (0: undecided) of det[[x_i − y, |x_i − y|² − (w_i − w_y)]] over the d + 1 vertices of
// each full simplex: the power test of y against the simplex's orthogonal sphere.
// Thesis: §2.1.2 (power distance π_x; the weighted Delaunay complex, Definition 2.13).
Array<std::int8_t> insphere_filter(In<double, nb::ndim<2>> points, In<double, nb::ndim<1>> weights,
                                   In<std::int64_t, nb::ndim<2>> simplices, In<std::int64_t, nb::ndim<1>> y) {
    const std::size_t n = points.shape(0), d = points.shape(1), m = simplices.shape(0);
    check_order(d + 1);
    check_size(weights.shape(0), n, "weights: length (the number of points)");
    check_points(points, simplices, d + 1);
    check_size(y.shape(0), m, "y: length (the number of simplices)");
    check_indices(y.data(), m, n, "y");
    std::vector<std::int8_t> out(m, 0);
    {
        nb::gil_scoped_release release;
        insphere_rows(points.data(), weights.data(), d, simplices.data(), y.data(), m, out.data());
    }
    return to_numpy(std::move(out));
}

// orient_filter for one simplex v (d + 1 point indices).  Thesis: §2.1.2 (orientation predicate).
int orient_one(In<double, nb::ndim<2>> points, In<std::int64_t, nb::ndim<1>> v) {
    const std::size_t d = points.shape(1);
    check_order(d);
    check_size(v.shape(0), d + 1, "v: length (the dimension + 1)");
    check_indices(v.data(), v.size(), points.shape(0), "v");
    std::int8_t out = 0;
    orient_rows(points.data(), d, v.data(), 1, &out);
    return out;
}

// insphere_filter for one full simplex v and point y.  Thesis: §2.1.2 (power test).
int insphere_one(In<double, nb::ndim<2>> points, In<double, nb::ndim<1>> weights, In<std::int64_t, nb::ndim<1>> v,
                 std::int64_t y) {
    const std::size_t n = points.shape(0), d = points.shape(1);
    check_order(d + 1);
    check_size(weights.shape(0), n, "weights: length (the number of points)");
    check_size(v.shape(0), d + 1, "v: length (the dimension + 1)");
    check_indices(v.data(), v.size(), n, "v");
    check_indices(&y, 1, n, "y");
    std::int8_t out = 0;
    insphere_rows(points.data(), weights.data(), d, v.data(), &y, 1, &out);
    return out;
}

namespace {

// Gauss–Jordan with partial pivoting of the k × k matrix mat into inv (work: scratch); false if
// (numerically) singular.  Thesis: §2.1.2 (the orthogonal sphere's linear system).
bool invert(const double* mat, std::size_t k, double* inv, double* work) {
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
            work[i * k + j] = mat[i * k + j];
            inv[i * k + j] = i == j ? 1.0 : 0.0;
        }
    }
    for (std::size_t col = 0; col < k; ++col) {
        const auto [piv, best] = pivot_row(work, k, col, k);
        if (best == 0.0) return false;
        if (piv != col) {
            for (std::size_t j = 0; j < k; ++j) {
                std::swap(work[col * k + j], work[piv * k + j]);
                std::swap(inv[col * k + j], inv[piv * k + j]);
            }
        }
        const double p = work[col * k + col];
        for (std::size_t j = 0; j < k; ++j) {
            work[col * k + j] /= p;
            inv[col * k + j] /= p;
        }
        for (std::size_t r = 0; r < k; ++r) {
            if (r != col) {
                const double f = work[r * k + col];
                if (f != 0.0) {
                    for (std::size_t j = 0; j < k; ++j) {
                        work[r * k + j] -= f * work[col * k + j];
                        inv[r * k + j] -= f * inv[col * k + j];
                    }
                }
            }
        }
    }
    return true;
}

}  // namespace

// Smallest orthogonal spheres of k-simplices in floating point.  For each row the system is set up
// from every vertex in turn until one has Frobenius condition number κ <= 10 (else the best is kept):
// A off = rhs for k = d, the Gram system A Aᵀ λ = rhs, off = Aᵀ λ, for k < d, with rows
// a_i = x_i − x_o and rhs_i = (|a_i|² − w_i + w_o) / 2.  Returns centre (m, d), r² (m,), an error
// estimate of the centre (m,) and a flag (m,) for the rows whose amplification
// κ·(1 + (|off|² + |w_o|)/|r²|) exceeds max_amplification (to be recomputed exactly).
// Thesis: §2.1.2 and Definition 2.14 (the smallest orthogonal sphere giving a simplex's alpha value).
std::tuple<Array<double>, Array<double>, Array<double>, Array<bool>> orthoball_float(
    In<double, nb::ndim<2>> points, In<double, nb::ndim<1>> weights, In<std::int64_t, nb::ndim<2>> simplices,
    double max_amplification) {
    const std::size_t n = points.shape(0), d = points.shape(1);
    const std::size_t m = simplices.shape(0), w = simplices.shape(1);
    check_size(weights.shape(0), n, "weights: length (the number of points)");
    if (w < 1) throw std::invalid_argument("simplices: at least one column expected");
    check_indices(simplices.data(), simplices.size(), n, "simplices");
    const std::size_t k = w - 1;
    std::vector<double> centre(m * d), r2(m), err(m);
    auto flag = bool_buffer(m);
    const double* P = points.data();
    const double* W = weights.data();
    const std::int64_t* S = simplices.data();
    {
        nb::gil_scoped_release release;
        std::vector<double> a(k * d), rhs(k), mat(k * k), inv(k * k), work(k * k), best_inv(k * k), best_a(k * d),
            best_rhs(k), lam(k);
        const double inf = std::numeric_limits<double>::infinity();
        for (std::size_t r = 0; r < m; ++r) {
            const std::int64_t* row = S + r * w;
            double best_kappa = inf;
            std::int64_t best_o = 0;
            for (std::size_t oi = 0; oi < w; ++oi) {
                const std::int64_t o = row[oi];
                std::size_t rr = 0;
                for (std::size_t i = 0; i < w; ++i) {
                    if (i == oi) continue;
                    const std::int64_t v = row[i];
                    double sq = 0.0;
                    for (std::size_t t = 0; t < d; ++t) {
                        const double x = P[v * d + t] - P[o * d + t];
                        a[rr * d + t] = x;
                        sq += x * x;
                    }
                    rhs[rr] = 0.5 * (sq - W[v] + W[o]);
                    ++rr;
                }
                if (k == d) {
                    for (std::size_t i = 0; i < k; ++i)
                        for (std::size_t j = 0; j < k; ++j) mat[i * k + j] = a[i * d + j];
                } else {
                    for (std::size_t i = 0; i < k; ++i) {
                        for (std::size_t j = 0; j < k; ++j) {
                            double s = 0.0;
                            for (std::size_t t = 0; t < d; ++t) s += a[i * d + t] * a[j * d + t];
                            mat[i * k + j] = s;
                        }
                    }
                }
                if (!invert(mat.data(), k, inv.data(), work.data())) continue;
                double n1 = 0.0, n2 = 0.0;
                for (std::size_t i = 0; i < k; ++i) {
                    for (std::size_t j = 0; j < k; ++j) {
                        n1 += mat[i * k + j] * mat[i * k + j];
                        n2 += inv[i * k + j] * inv[i * k + j];
                    }
                }
                const double kappa = std::sqrt(n1 * n2);
                if (kappa < best_kappa) {
                    best_kappa = kappa;
                    best_o = o;
                    for (std::size_t i = 0; i < k; ++i) {
                        best_rhs[i] = rhs[i];
                        for (std::size_t j = 0; j < k; ++j) best_inv[i * k + j] = inv[i * k + j];
                        for (std::size_t t = 0; t < d; ++t) best_a[i * d + t] = a[i * d + t];
                    }
                }
                if (best_kappa <= 10.0) break;
            }
            if (best_kappa == inf) {
                flag[r] = true;
                for (std::size_t t = 0; t < d; ++t) centre[r * d + t] = P[row[0] * d + t];
                r2[r] = std::numeric_limits<double>::quiet_NaN();
                err[r] = inf;
                continue;
            }
            // λ = best_inv · best_rhs (the original recomputed it for every coordinate, identically)
            for (std::size_t i = 0; i < k; ++i) {
                double l = 0.0;
                for (std::size_t j = 0; j < k; ++j) l += best_inv[i * k + j] * best_rhs[j];
                lam[i] = l;
            }
            double off2 = 0.0, asq = 0.0;
            for (std::size_t t = 0; t < d; ++t) {
                double c = 0.0;
                for (std::size_t i = 0; i < k; ++i) {
                    if (k == d) {
                        if (i == t) c = lam[i];
                    } else {
                        c += lam[i] * best_a[i * d + t];
                    }
                }
                centre[r * d + t] = P[best_o * d + t] + c;
                off2 += c * c;
            }
            for (std::size_t i = 0; i < k; ++i)
                for (std::size_t t = 0; t < d; ++t) asq += best_a[i * d + t] * best_a[i * d + t];
            const double w0 = W[best_o];
            const double rr2 = off2 - w0;
            r2[r] = rr2;
            const double amp = rr2 == 0.0 ? inf : best_kappa * (1.0 + (off2 + std::fabs(w0)) / std::fabs(rr2));
            flag[r] = !(amp <= max_amplification);
            err[r] = 16.0 * kU * best_kappa * std::sqrt(off2 + asq);
        }
    }
    return {to_numpy(std::move(centre), {m, d}), to_numpy(std::move(r2)), to_numpy(std::move(err)),
            to_numpy(std::move(flag), m)};
}

// Certain signs (0: undecided) of π_y(c) − r² for the orthoballs (c, r²) of faces[face_idx], given the
// centres' error bounds err.  Thesis: §2.1.2 and Definition 2.14 (is a face attached?).
Array<std::int8_t> power_filter(In<double, nb::ndim<2>> points, In<double, nb::ndim<1>> weights,
                                In<double, nb::ndim<2>> centre, In<double, nb::ndim<1>> r2,
                                In<double, nb::ndim<1>> err, In<std::int64_t, nb::ndim<2>> faces,
                                In<std::int64_t, nb::ndim<1>> face_idx, In<std::int64_t, nb::ndim<1>> y) {
    const std::size_t n = points.shape(0), d = points.shape(1);
    const std::size_t nf = faces.shape(0), m = face_idx.shape(0);
    check_size(weights.shape(0), n, "weights: length (the number of points)");
    check_size(centre.shape(0), nf, "centre: rows (the number of faces)");
    check_size(centre.shape(1), d, "centre: columns (the dimension)");
    check_size(r2.shape(0), nf, "r2: length (the number of faces)");
    check_size(err.shape(0), nf, "err: length (the number of faces)");
    if (faces.shape(1) < 1) throw std::invalid_argument("faces: at least one column expected");
    check_indices(faces.data(), faces.size(), n, "faces");
    check_indices(face_idx.data(), m, nf, "face_idx");
    check_size(y.shape(0), m, "y: length (the number of tests)");
    check_indices(y.data(), m, n, "y");
    std::vector<std::int8_t> out(m, 0);
    const double* P = points.data();
    const double* W = weights.data();
    const double* C = centre.data();
    const double* R2 = r2.data();
    const double* E = err.data();
    const std::int64_t* F = faces.data();
    const std::size_t fw = faces.shape(1);
    {
        nb::gil_scoped_release release;
        for (std::size_t r = 0; r < m; ++r) {
            const std::int64_t f = face_idx.data()[r];
            const std::int64_t q = y.data()[r];
            const std::int64_t x0 = F[f * fw];
            double dist2 = 0.0, off2 = 0.0;
            for (std::size_t t = 0; t < d; ++t) {
                const double dc = C[f * d + t] - P[q * d + t];
                dist2 += dc * dc;
                const double dn = C[f * d + t] - P[x0 * d + t];
                off2 += dn * dn;
            }
            const double power = dist2 - W[q] - R2[f];
            const double e = E[f];
            const double scale = dist2 + std::fabs(W[q]) + std::fabs(R2[f]) + off2;
            const double bound = 4.0 * (std::sqrt(dist2) + std::sqrt(off2) + e) * e + 16.0 * kU * scale + kTiny;
            if (power > bound) {
                out[r] = 1;
            } else if (power < -bound) {
                out[r] = -1;
            }
        }
    }
    return to_numpy(std::move(out));
}

}  // namespace thesis

NB_MODULE(predicate_filters, m) {
    namespace nb = nanobind;
    m.doc() = "Floating-point filters of the orientation, power and orthogonal-sphere predicates (thesis §2.1.2).";
    m.def("orient_filter", &thesis::orient_filter, nb::arg("points"), nb::arg("simplices"));
    m.def("insphere_filter", &thesis::insphere_filter, nb::arg("points"), nb::arg("weights"), nb::arg("simplices"),
          nb::arg("y"));
    m.def("orient_one", &thesis::orient_one, nb::arg("points"), nb::arg("v"));
    m.def("insphere_one", &thesis::insphere_one, nb::arg("points"), nb::arg("weights"), nb::arg("v"), nb::arg("y"));
    m.def("orthoball_float", &thesis::orthoball_float, nb::arg("points"), nb::arg("weights"), nb::arg("simplices"),
          nb::arg("max_amplification"));
    m.def("power_filter", &thesis::power_filter, nb::arg("points"), nb::arg("weights"), nb::arg("centre"),
          nb::arg("r2"), nb::arg("err"), nb::arg("faces"), nb::arg("face_idx"), nb::arg("y"));
}
