// Smith normal form mod primes: the word-size kernels of the exact Smith form of a dense integer
// matrix by modular arithmetic (driven by thesis_lib/homology/_modular.py): rank profiles and determinants with
// adjugates modulo 26-bit primes (float64 residues), inverses modulo a 31-bit prime, and p-adic digits
// of b⁻¹ y (Dixon).  The drivers (Chinese remaindering, rational reconstruction, the Smith form over
// Z/M) stay in Python on Python integers.
#include "arrays.hpp"
#include "column_heap.hpp"

#include <nanobind/stl/tuple.h>

#include <cmath>
#include <tuple>

namespace thesis {

namespace {

// Float64 residues: the product of two residues below 2^26 is exact.
constexpr std::int64_t kMaxFloatPrime = std::int64_t(1) << 26;
// Int64 residues: the product of two residues below 2^31 fits.
constexpr std::int64_t kMaxWordPrime = std::int64_t(1) << 31;
constexpr std::int64_t kBound62 = std::int64_t(1) << 62;

// floor(y) for |y| < 2^31, exactly: truncation toward zero through int32, one step down for a negative
// non-integer y.  Plain arithmetic where std::floor is a library call without SSE4.1.  Every y here is
// below 2^28 in magnitude (the checked inputs guarantee it): y = x / p with |x| < 2 p² + p, residues in
// [0, p) and factors f within [-p, 2p), p <= 2^26.  -0.0 never occurs (no residue is -0.0, and
// floor(+0.0) = +0.0 both ways).
inline double floor_small(double y) {
    const double t = static_cast<double>(static_cast<std::int32_t>(y));
    return t > y ? t - 1.0 : t;
}

// (d - f s) mod p for float64 residues below 2^26: f·s < 2^52 is exact, and x - p·floor(x/p) reduces
// without an integer division.
inline double sub_mod(double d, double s, double f, double p, double inv_p) {
    double x = d - f * s;
    x -= p * floor_small(x * inv_p);
    x = x < 0 ? x + p : x;  // = `if x < 0: x += p elif x >= p: x -= p` (x + p < p when x < 0)
    x = x >= p ? x - p : x;
    return x;
}

// The columns a row operation touches: idx[0, n_idx) when n_idx >= 0 (the non-zero columns of a
// sparse pivot row), else the range [lo, hi).
struct ColumnSet {
    const std::int64_t* idx;
    std::int64_t n_idx, lo, hi;
};

// dst[c] = (dst[c] - f src[c]) mod p over the columns c of cols.
// Thesis: Theorem 2.20 (row operation 3: row i + q row j), over Z_p.
inline void axpy(double* dst, const double* src, double f, double p, double inv_p, const ColumnSet& cols) {
    const std::int64_t* idx = cols.idx;
    const std::int64_t n_idx = cols.n_idx, lo = cols.lo, hi = cols.hi;
    if (n_idx >= 0) {
        for (std::int64_t t = 0; t < n_idx; ++t) {
            const std::int64_t c = idx[t];
            dst[c] = sub_mod(dst[c], src[c], f, p, inv_p);
        }
    } else {
        for (std::int64_t c = lo; c < hi; ++c) dst[c] = sub_mod(dst[c], src[c], f, p, inv_p);
    }
}

// The first row i in [k, r) with a[i, k] != 0, or -1 (a of n columns, row-major).
template <class T>
inline std::int64_t pivot_row(const T* a, std::int64_t n, std::int64_t k, std::int64_t r) {
    for (std::int64_t i = k; i < r; ++i)
        if (a[i * n + k] != 0) return i;
    return -1;
}

void check_float_prime(std::int64_t p) {
    if (p < 2 || p > kMaxFloatPrime) throw std::invalid_argument("p must be a prime in [2, 2^26]");
}

// Every entry an integer in [0, p) (NaN refused).
void check_residues(const double* a, std::size_t count, double p, const char* name) {
    for (std::size_t e = 0; e < count; ++e) {
        const double x = a[e];
        if (!(x >= 0.0 && x < p) || x != std::floor(x))
            throw std::invalid_argument(std::string(name) + " must hold integer residues in [0, p)");
    }
}

}  // namespace

// Row echelon form of a (float64 residues mod p < 2^26, overwritten): the pivot rows and columns, so
// that a[rows][:, cols] is invertible mod p.
// Thesis: §2.2.1 (rank over Z_p, where every nonzero pivot is invertible).
std::tuple<Array<std::int64_t>, Array<std::int64_t>> rank_profile(Out<double, nb::ndim<2>> a_arr, std::int64_t p) {
    check_float_prime(p);
    const std::int64_t m = static_cast<std::int64_t>(a_arr.shape(0));
    const std::int64_t n = static_cast<std::int64_t>(a_arr.shape(1));
    double* a = a_arr.data();
    check_residues(a, static_cast<std::size_t>(m * n), static_cast<double>(p), "a");
    std::vector<std::int64_t> rows, cols;
    {
        nb::gil_scoped_release release;
        const double fp = static_cast<double>(p);
        const double inv_p = 1.0 / fp;
        std::vector<std::int64_t> order(static_cast<std::size_t>(m));
        for (std::int64_t i = 0; i < m; ++i) order[i] = i;
        rows.reserve(static_cast<std::size_t>(std::min(m, n)));
        cols.reserve(static_cast<std::size_t>(std::min(m, n)));
        std::vector<std::int64_t> idx(static_cast<std::size_t>(n));
        std::int64_t k = 0;
        for (std::int64_t j = 0; j < n; ++j) {
            if (k == m) break;
            std::int64_t sel = -1;
            for (std::int64_t i = k; i < m; ++i) {
                if (a[i * n + j] != 0) {
                    sel = i;
                    break;
                }
            }
            if (sel < 0) continue;
            double* rk = a + k * n;
            if (sel != k) {
                double* rs = a + sel * n;
                for (std::int64_t c = j; c < n; ++c) std::swap(rk[c], rs[c]);
                std::swap(order[k], order[sel]);
            }
            const double inv = static_cast<double>(mod_inverse(static_cast<std::int64_t>(rk[j]), p));
            std::int64_t nnz = 0;
            for (std::int64_t c = j; c < n; ++c) {
                if (rk[c] != 0) {
                    idx[nnz] = c;
                    ++nnz;
                }
            }
            const std::int64_t sparse = 2 * nnz < n - j ? nnz : -1;
            const ColumnSet touched{idx.data(), sparse, j, n};
            for (std::int64_t i = k + 1; i < m; ++i) {
                double* ri = a + i * n;
                if (ri[j] != 0) {
                    double f = ri[j] * inv;
                    f -= fp * floor_small(f * inv_p);
                    axpy(ri, rk, f, fp, inv_p, touched);
                }
            }
            rows.push_back(order[k]);
            cols.push_back(j);
            ++k;
        }
    }
    return {to_numpy(std::move(rows)), to_numpy(std::move(cols))};
}

// (det b mod p, adj(b) y mod p, ok) by LU of [b | y] mod p (float64 residues, p < 2^26), then back
// substitution scaled by det (adj(b) y = det · b⁻¹ y); ok is false if p divides det b.
// Thesis: Theorem 2.20 (the product of the invariant factors is a determinant), by elementary row operations.
std::tuple<std::int64_t, Array<std::int64_t>, bool> det_adjugate(In<double, nb::ndim<2>> b_arr,
                                                                 In<double, nb::ndim<2>> y_arr, std::int64_t p) {
    check_float_prime(p);
    const std::int64_t r = static_cast<std::int64_t>(b_arr.shape(0));
    if (static_cast<std::int64_t>(b_arr.shape(1)) != r) throw std::invalid_argument("b must be square");
    if (static_cast<std::int64_t>(y_arr.shape(0)) != r) throw std::invalid_argument("y must have as many rows as b");
    const std::int64_t t = static_cast<std::int64_t>(y_arr.shape(1));
    const double* B = b_arr.data();
    const double* Y = y_arr.data();
    check_residues(B, static_cast<std::size_t>(r * r), static_cast<double>(p), "b");
    check_residues(Y, static_cast<std::size_t>(r * t), static_cast<double>(p), "y");
    std::vector<std::int64_t> z(static_cast<std::size_t>(r * t), 0);
    std::int64_t det = 1;
    bool ok = true;
    {
        nb::gil_scoped_release release;
        const double fp = static_cast<double>(p);
        const double inv_p = 1.0 / fp;
        const std::int64_t w = r + t;
        std::vector<double> a(static_cast<std::size_t>(r * w));  // eliminate [b | y] together
        for (std::int64_t i = 0; i < r; ++i) {
            for (std::int64_t c = 0; c < r; ++c) a[i * w + c] = B[i * r + c];
            for (std::int64_t c = 0; c < t; ++c) a[i * w + r + c] = Y[i * t + c];
        }
        double* A = a.data();
        for (std::int64_t k = 0; k < r && ok; ++k) {
            const std::int64_t sel = pivot_row(A, w, k, r);
            if (sel < 0) {
                ok = false;
                break;
            }
            double* rk = A + k * w;
            if (sel != k) {
                double* rs = A + sel * w;
                for (std::int64_t c = k; c < w; ++c) std::swap(rk[c], rs[c]);
                det = p - det;
            }
            det = det * static_cast<std::int64_t>(rk[k]) % p;
            const double inv = static_cast<double>(mod_inverse(static_cast<std::int64_t>(rk[k]), p));
            const ColumnSet right{nullptr, -1, k + 1, w};  // the columns right of the pivot
            for (std::int64_t i = k + 1; i < r; ++i) {
                double* ri = A + i * w;
                if (ri[k] != 0) {
                    double f = ri[k] * inv;
                    f -= fp * floor_small(f * inv_p);
                    axpy(ri, rk, f, fp, inv_p, right);
                }
            }
        }
        if (ok) {
            for (std::int64_t k = r - 1; k >= 0; --k) {  // back substitution, then scale by det
                const double* rk = A + k * w;
                const std::int64_t inv = mod_inverse(static_cast<std::int64_t>(rk[k]), p);
                for (std::int64_t c = 0; c < t; ++c) {
                    std::int64_t s = static_cast<std::int64_t>(rk[r + c]);
                    for (std::int64_t u = k + 1; u < r; ++u)
                        s = floor_mod(s - static_cast<std::int64_t>(rk[u]) * z[u * t + c], p);
                    z[k * t + c] = s * inv % p;
                }
            }
            for (std::int64_t e = 0; e < r * t; ++e) z[e] = z[e] * det % p;
        } else {
            det = 0;
            std::fill(z.begin(), z.end(), 0);
        }
    }
    return {det, to_numpy(std::move(z), {static_cast<std::size_t>(r), static_cast<std::size_t>(t)}), ok};
}

// b⁻¹ mod p by Gauss–Jordan (int64, p < 2^31), and whether b is invertible mod p.
// Thesis: Theorem 2.20 (elementary row operations over Z_p).
std::tuple<Array<std::int64_t>, bool> inverse_mod(In<std::int64_t, nb::ndim<2>> b_arr, std::int64_t p) {
    if (p < 2 || p >= kMaxWordPrime) throw std::invalid_argument("p must be a prime below 2^31");
    const std::int64_t r = static_cast<std::int64_t>(b_arr.shape(0));
    if (static_cast<std::int64_t>(b_arr.shape(1)) != r) throw std::invalid_argument("b must be square");
    const std::int64_t* B = b_arr.data();
    std::vector<std::int64_t> inv(static_cast<std::size_t>(r * r), 0);
    bool ok = true;
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> a(static_cast<std::size_t>(r * r));
        for (std::int64_t e = 0; e < r * r; ++e) a[e] = floor_mod(B[e], p);
        for (std::int64_t i = 0; i < r; ++i) inv[i * r + i] = 1;
        std::int64_t* A = a.data();
        std::int64_t* I = inv.data();
        for (std::int64_t k = 0; k < r; ++k) {
            const std::int64_t sel = pivot_row(A, r, k, r);
            if (sel < 0) {
                ok = false;
                break;
            }
            if (sel != k) {
                for (std::int64_t c = 0; c < r; ++c) {
                    std::swap(A[k * r + c], A[sel * r + c]);
                    std::swap(I[k * r + c], I[sel * r + c]);
                }
            }
            const std::int64_t f = mod_inverse(A[k * r + k], p);
            for (std::int64_t c = 0; c < r; ++c) {
                A[k * r + c] = A[k * r + c] * f % p;
                I[k * r + c] = I[k * r + c] * f % p;
            }
            for (std::int64_t i = 0; i < r; ++i) {
                const std::int64_t g = A[i * r + k];
                if (i != k && g != 0) {
                    for (std::int64_t c = 0; c < r; ++c) {
                        A[i * r + c] = floor_mod(A[i * r + c] - g * A[k * r + c], p);
                        I[i * r + c] = floor_mod(I[i * r + c] - g * I[k * r + c], p);
                    }
                }
            }
        }
    }
    return {to_numpy(std::move(inv), {static_cast<std::size_t>(r), static_cast<std::size_t>(r)}), ok};
}

// `steps` more p-adic digits of x = b⁻¹ y (Dixon) from the residual res (updated in place):
// x ≡ Σ_i digits[i] p^i; each step solves b d ≡ res (mod p) with binv and sets res = (res - b d) / p.
// Needs r·max|b|·(p - 1) < 2^62 and |res| < 2^62 (then every partial sum fits in int64, and so does
// the next residual).
// Thesis: Theorem 2.20 (the determinant of a nonsingular minor, found from b⁻¹ y).
Array<std::int64_t> dixon_digits(In<std::int64_t, nb::ndim<2>> b_arr, In<std::int64_t, nb::ndim<2>> binv_arr,
                                 Out<std::int64_t, nb::ndim<2>> res_arr, std::int64_t p, std::int64_t steps) {
    if (p < 2 || p > kMaxWordPrime) throw std::invalid_argument("p must be a prime in [2, 2^31]");
    if (steps < 0) throw std::invalid_argument("steps must be non-negative");
    const std::int64_t r = static_cast<std::int64_t>(b_arr.shape(0));
    if (static_cast<std::int64_t>(b_arr.shape(1)) != r) throw std::invalid_argument("b must be square");
    if (static_cast<std::int64_t>(binv_arr.shape(0)) != r || static_cast<std::int64_t>(binv_arr.shape(1)) != r)
        throw std::invalid_argument("binv must have the shape of b");
    if (static_cast<std::int64_t>(res_arr.shape(0)) != r) throw std::invalid_argument("res must have as many rows as b");
    const std::int64_t t = static_cast<std::int64_t>(res_arr.shape(1));
    const std::int64_t* B = b_arr.data();
    const std::int64_t* Binv = binv_arr.data();
    std::int64_t* R = res_arr.data();
    std::uint64_t big = 0;
    for (std::int64_t e = 0; e < r * r; ++e) {
        const std::uint64_t mag = B[e] < 0 ? 0 - static_cast<std::uint64_t>(B[e]) : static_cast<std::uint64_t>(B[e]);
        big = std::max(big, mag);
        if (Binv[e] < 0 || Binv[e] >= p) throw std::invalid_argument("binv must hold residues in [0, p)");
    }
    if (r > 0 && big > 0 && big > static_cast<std::uint64_t>((kBound62 - 1) / r / (p - 1)))
        throw std::invalid_argument("r * max|b| * (p - 1) must stay below 2^62");
    for (std::int64_t e = 0; e < r * t; ++e)
        if (R[e] >= kBound62 || R[e] <= -kBound62) throw std::invalid_argument("|res| must stay below 2^62");
    std::vector<std::int64_t> digits(static_cast<std::size_t>(steps * r * t));
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> rm(static_cast<std::size_t>(r));
        for (std::int64_t i = 0; i < steps; ++i) {
            std::int64_t* D = digits.data() + i * r * t;
            for (std::int64_t c = 0; c < t; ++c) {
                for (std::int64_t u = 0; u < r; ++u) rm[u] = floor_mod(R[u * t + c], p);
                for (std::int64_t k = 0; k < r; ++k) {
                    std::int64_t acc = 0;
                    for (std::int64_t u = 0; u < r; ++u) acc = (acc + Binv[k * r + u] * rm[u]) % p;
                    D[k * t + c] = acc;
                }
                for (std::int64_t k = 0; k < r; ++k) {
                    std::int64_t acc = R[k * t + c];
                    for (std::int64_t u = 0; u < r; ++u) acc -= B[k * r + u] * D[u * t + c];
                    R[k * t + c] = floor_div(acc, p);  // exact when b d ≡ res (mod p)
                }
            }
        }
    }
    return to_numpy(std::move(digits), {static_cast<std::size_t>(steps), static_cast<std::size_t>(r),
                                        static_cast<std::size_t>(t)});
}

}  // namespace thesis

NB_MODULE(modular_smith, m) {
    m.doc() = "Smith normal form mod primes: rank profiles, determinants, inverses and p-adic digits (thesis Theorem 2.20).";
    m.def("rank_profile", &thesis::rank_profile, nanobind::arg("a").noconvert(), nanobind::arg("p"));
    m.def("det_adjugate", &thesis::det_adjugate, nanobind::arg("b"), nanobind::arg("y"), nanobind::arg("p"));
    m.def("inverse_mod", &thesis::inverse_mod, nanobind::arg("b"), nanobind::arg("p"));
    m.def("dixon_digits", &thesis::dixon_digits, nanobind::arg("b"), nanobind::arg("binv"),
          nanobind::arg("res").noconvert(), nanobind::arg("p"), nanobind::arg("steps"));
}
