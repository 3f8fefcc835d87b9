// The trimming step of the Crust (ABK98, step 5) for n-simplices in R^{n+1}: sharp ridges, the
// outer walk about the ridges, and the greedy manifold of the walked simplices (thesis §3.4).
#include "arrays.hpp"

#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <tuple>

namespace thesis {

// Python's x % y for floats (the sign of y; a zero remainder is +0 for y > 0), as numba computes it.
inline double py_fmod(double x, double y) {
    double mod = std::fmod(x, y);
    if (mod != 0.0) {
        if ((y < 0) != (mod < 0)) mod += y;
    } else {
        mod = std::copysign(0.0, y);
    }
    return mod;
}

// numpy's (u * w).sum() in numba: a left-to-right loop from 0.0.
inline double dot(const double* u, const double* w, std::int64_t d) {
    double c = 0.0;
    for (std::int64_t a = 0; a < d; ++a) c += u[a] * w[a];
    return c;
}

const double TWO_PI = 2 * M_PI;

// The samples (N, d) and the vertex count k1 = n + 1 of the simplices (d = k1).
struct Geom {
    const double* pts;
    std::int64_t N, d, k1;
    const double* point(std::int64_t i) const { return pts + i * d; }
};

// Refuse ridge incidences (start (R + 1,), tri_of and opp (slots,)) that address rows outside
// m simplices and N samples.
void check_incidence(const char* who, std::int64_t R, std::int64_t m, std::int64_t N,
                     const In<std::int64_t, nb::ndim<1>>& start, const In<std::int64_t, nb::ndim<1>>& tri_of,
                     const In<std::int64_t, nb::ndim<1>>& opp) {
    const std::string w(who);
    if (static_cast<std::int64_t>(start.shape(0)) != R + 1) throw std::invalid_argument(w + ": start must have R + 1 entries");
    const std::int64_t slots = static_cast<std::int64_t>(tri_of.shape(0));
    if (static_cast<std::int64_t>(opp.shape(0)) != slots)
        throw std::invalid_argument(w + ": tri_of and opp must have the same length");
    const std::int64_t* ST = start.data();
    if (ST[0] < 0 || ST[R] > slots) throw std::invalid_argument(w + ": start is out of range");
    for (std::int64_t e = 0; e < R; ++e)
        if (ST[e + 1] < ST[e]) throw std::invalid_argument(w + ": start must be non-decreasing");
    const std::int64_t *TO = tri_of.data(), *OP = opp.data();
    for (std::int64_t i = 0; i < slots; ++i) {
        if (TO[i] < 0 || TO[i] >= m) throw std::invalid_argument(w + ": tri_of is outside 0..m-1");
        if (OP[i] < 0 || OP[i] >= N) throw std::invalid_argument(w + ": opp is outside 0..N-1");
    }
}

// Refuse ridges (R, n) with pts (N, n + 1), n >= 1, or a vertex outside 0..N-1; the geometry.
Geom check_ridges(const char* who, const In<double, nb::ndim<2>>& pts, const In<std::int64_t, nb::ndim<2>>& ridges) {
    const std::string w(who);
    Geom g{pts.data(), static_cast<std::int64_t>(pts.shape(0)), static_cast<std::int64_t>(pts.shape(1)),
           static_cast<std::int64_t>(ridges.shape(1)) + 1};
    if (g.k1 < 2 || g.k1 > 64 || g.d != g.k1)
        throw std::invalid_argument(w + ": ridges must have shape (R, n), 1 <= n < 64, and pts (N, n + 1)");
    const std::int64_t R = static_cast<std::int64_t>(ridges.shape(0));
    const std::int64_t* RI = ridges.data();
    for (std::int64_t i = 0; i < R * (g.k1 - 1); ++i)
        if (RI[i] < 0 || RI[i] >= g.N) throw std::invalid_argument(w + ": a ridge vertex is outside 0..N-1");
    return g;
}

// Refuse simplices (m, n + 1) and ridge_of (m, n + 1) that do not match the geometry and R ridges.
void check_simplices(const char* who, const Geom& g, std::int64_t R, const In<std::int64_t, nb::ndim<2>>& simplices,
                     const In<std::int64_t, nb::ndim<2>>& ridge_of) {
    const std::string w(who);
    const std::int64_t m = static_cast<std::int64_t>(simplices.shape(0));
    if (static_cast<std::int64_t>(simplices.shape(1)) != g.k1)
        throw std::invalid_argument(w + ": simplices must have shape (m, n + 1)");
    if (static_cast<std::int64_t>(ridge_of.shape(0)) != m || static_cast<std::int64_t>(ridge_of.shape(1)) != g.k1)
        throw std::invalid_argument(w + ": ridge_of must have the shape of simplices");
    const std::int64_t *S = simplices.data(), *RO = ridge_of.data();
    for (std::int64_t i = 0; i < m * g.k1; ++i) {
        if (S[i] < 0 || S[i] >= g.N) throw std::invalid_argument(w + ": a simplex vertex is outside 0..N-1");
        if (RO[i] < 0 || RO[i] >= R) throw std::invalid_argument(w + ": ridge_of is outside 0..R-1");
    }
}

// Rows p_{i+1} − p_0 for the vertices verts (k + 1) of a simplex, into e (k, d).
// Thesis: §3.4 (the candidate simplices of the Crust and their edge vectors).
void edge_vectors(const Geom& g, const std::int64_t* verts, std::int64_t nverts, double* e) {
    const double* p0 = g.point(verts[0]);
    for (std::int64_t i = 0; i + 1 < nverts; ++i) {
        const double* p = g.point(verts[i + 1]);
        for (std::int64_t a = 0; a < g.d; ++a) e[i * g.d + a] = p[a] - p0[a];
    }
}

// Orthonormal basis (rows of q, n - 1 of them) of the directions of the ridge's affine span
// (Gram–Schmidt).  Thesis: §3.4 ("Triangulations": the normal plane of an edge).
void complement_basis(const Geom& g, const std::int64_t* ridge, double* q) {
    const std::int64_t nr = g.k1 - 1, d = g.d;
    edge_vectors(g, ridge, nr, q);
    for (std::int64_t i = 0; i + 1 < nr; ++i) {
        double* qi = q + i * d;
        for (std::int64_t j = 0; j < i; ++j) {
            const double* qj = q + j * d;
            const double c = dot(qi, qj, d);
            for (std::int64_t a = 0; a < d; ++a) qi[a] = qi[a] - c * qj[a];
        }
        const double norm = std::sqrt(dot(qi, qi, d)) + 1e-300;
        for (std::int64_t a = 0; a < d; ++a) qi[a] = qi[a] / norm;
    }
}

// w minus its projection on the span of the nq rows of q, in place.
// Thesis: §3.4 (the directions of the simplices about a ridge, in its normal plane).
void project(double* w, const double* q, std::int64_t nq, std::int64_t d) {
    for (std::int64_t j = 0; j < nq; ++j) {
        const double c = dot(w, q + j * d, d);
        for (std::int64_t a = 0; a < d; ++a) w[a] = w[a] - c * q[j * d + a];
    }
}

// np.linalg.det of the n × n matrix A (row-major, overwritten) as numba computes it: sgn ·
// exp(Σ log |u_kk|) over the LU factors of LAPACK's getrf (OpenBLAS's left-looking unblocked getf2:
// column j gets its pivots, its U part by dot products, its L part by a matrix-vector product, then
// partial pivoting on the first largest |.| and scaling by the reciprocal pivot); 0 when a pivot is 0.
// Verified bit for bit against numba for n = 1, 2, 3 (the Crust's n).
// Thesis: §3.4 (the oriented normal of a candidate simplex), Theorem 3.18 (Gram determinants).
double numba_det(double* A, std::int64_t n, std::int64_t* ipiv, double* b) {
    for (std::int64_t i = 0; i < n * n; ++i)
        if (!std::isfinite(A[i])) throw std::invalid_argument("Array must not contain infs or NaNs.");
    bool singular = false;
    for (std::int64_t j = 0; j < n; ++j) {
        for (std::int64_t i = 0; i < n; ++i) b[i] = A[i * n + j];
        for (std::int64_t i = 0; i < j; ++i)
            if (ipiv[i] != i) std::swap(b[i], b[ipiv[i]]);
        for (std::int64_t i = 1; i < j; ++i) {
            double s = 0.0;
            for (std::int64_t k = 0; k < i; ++k) s += A[i * n + k] * b[k];
            b[i] -= s;
        }
        for (std::int64_t i = j; i < n; ++i) {
            double s = 0.0;
            for (std::int64_t k = 0; k < j; ++k) s += A[i * n + k] * b[k];
            b[i] -= s;
        }
        std::int64_t jp = j;
        for (std::int64_t i = j + 1; i < n; ++i)
            if (std::fabs(b[i]) > std::fabs(b[jp])) jp = i;
        ipiv[j] = jp;
        for (std::int64_t i = 0; i < n; ++i) A[i * n + j] = b[i];
        if (b[jp] != 0.0) {
            if (jp != j)
                for (std::int64_t k = 0; k <= j; ++k) std::swap(A[j * n + k], A[jp * n + k]);
            const double piv = A[j * n + j];
            if (std::fabs(piv) >= DBL_MIN) {
                const double r = 1.0 / piv;
                for (std::int64_t i = j + 1; i < n; ++i) A[i * n + j] *= r;
            } else {
                for (std::int64_t i = j + 1; i < n; ++i) A[i * n + j] /= piv;
            }
        } else {
            singular = true;
        }
    }
    if (singular) return 0.0 * std::exp(-INFINITY);
    std::int64_t swaps = 1;
    for (std::int64_t k = 0; k < n; ++k) swaps += ipiv[k] != k;
    double sgn = (swaps & 1) == 0 ? -1.0 : 1.0;
    double acc = 0.0;
    for (std::int64_t k = 0; k < n; ++k) {
        double v = A[k * n + k];
        if (v < 0.0) {
            sgn = -sgn;
            v = -v;
        }
        acc = acc + std::log(v);
    }
    return (sgn + 0.0) * std::exp(acc);
}

// Scratch space of the geometric helpers, allocated once per kernel call.
struct Scratch {
    std::vector<double> e, sub, b, q, w, wc, nrm, ref, y;
    std::vector<std::int64_t> ipiv;
    explicit Scratch(std::int64_t d)
        : e(d * d), sub(d * d), b(d), q(d * d), w(d), wc(d), nrm(d), ref(d), y(d), ipiv(d) {}
};

// Normal of the oriented simplex o (k1 vertices): cofactors of its edge vectors (the cross product
// for n = 2), normalised, into sc.nrm.  Thesis: §3.4 (orienting the Crust coherently), §3.1.1.
void oriented_normal(const Geom& g, const std::int64_t* o, Scratch& sc) {
    const std::int64_t n = g.k1 - 1, d = g.d;
    edge_vectors(g, o, g.k1, sc.e.data());
    for (std::int64_t k = 0; k < d; ++k) {
        for (std::int64_t i = 0; i < n; ++i) {
            std::int64_t c = 0;
            for (std::int64_t j = 0; j < d; ++j)
                if (j != k) sc.sub[i * n + c++] = sc.e[i * d + j];
        }
        const double sign = k % 2 == 0 ? 1.0 : -1.0;
        sc.nrm[k] = sign * numba_det(sc.sub.data(), n, sc.ipiv.data(), sc.b.data());
    }
    const double norm = std::sqrt(dot(sc.nrm.data(), sc.nrm.data(), d)) + 1e-300;
    for (std::int64_t a = 0; a < d; ++a) sc.nrm[a] = sc.nrm[a] / norm;
}

// +1 if the vertex list b is an even permutation of a, -1 if odd (same vertex sets).
// Thesis: §3.4 (coherent orientation across a ridge).
int parity(const std::int64_t* a, const std::int64_t* b, std::int64_t k) {
    std::int64_t perm[64] = {0};
    for (std::int64_t i = 0; i < k; ++i)
        for (std::int64_t j = 0; j < k; ++j)
            if (b[i] == a[j]) perm[i] = j;
    std::int64_t inv = 0;
    for (std::int64_t i = 0; i < k; ++i)
        for (std::int64_t j = i + 1; j < k; ++j)
            if (perm[i] > perm[j]) ++inv;
    return inv % 2 == 0 ? 1 : -1;
}

// Update sharp on the ridges todo: a ridge is sharp when one live simplex contains it, or all of them
// lie in a wedge < π/2 (the first 64 live ones are looked at).
// Thesis: §3.4, "Triangulations" (the trimming of [ABK98]: sharp edges).
void sharp_ridges(In<double, nb::ndim<2>> pts, In<std::int64_t, nb::ndim<2>> ridges, In<bool, nb::ndim<1>> alive,
                  In<std::int64_t, nb::ndim<1>> start, In<std::int64_t, nb::ndim<1>> tri_of,
                  In<std::int64_t, nb::ndim<1>> opp, In<std::int64_t, nb::ndim<1>> todo, Out<bool, nb::ndim<1>> sharp) {
    const Geom g = check_ridges("sharp_ridges", pts, ridges);
    const std::int64_t R = static_cast<std::int64_t>(ridges.shape(0)), k1 = g.k1, d = g.d;
    check_incidence("sharp_ridges", R, static_cast<std::int64_t>(alive.shape(0)), g.N, start, tri_of, opp);
    if (static_cast<std::int64_t>(sharp.shape(0)) != R) throw std::invalid_argument("sharp_ridges: sharp must have R entries");
    const std::int64_t *ST = start.data(), *RI = ridges.data(), *TO = tri_of.data(), *OP = opp.data(), *TD = todo.data();
    const std::int64_t n_todo = static_cast<std::int64_t>(todo.shape(0));
    for (std::int64_t i = 0; i < n_todo; ++i)
        if (TD[i] < 0 || TD[i] >= R) throw std::invalid_argument("sharp_ridges: todo is outside 0..R-1");
    const bool* AL = alive.data();
    bool* SH = sharp.data();
    const double* P = pts.data();
    nb::gil_scoped_release release;
    Scratch sc(d);
    double angles[64];
    const std::int64_t nq = k1 - 2;
    for (std::int64_t it = 0; it < n_todo; ++it) {
        const std::int64_t e = TD[it];
        SH[e] = false;
        const std::int64_t* ridge = RI + e * (k1 - 1);
        complement_basis(g, ridge, sc.q.data());
        const double* a = P + ridge[0] * d;
        std::fill(sc.ref.begin(), sc.ref.end(), 0.0);
        std::fill(sc.y.begin(), sc.y.end(), 0.0);
        bool got_ref = false, got_y = false;
        std::int64_t cnt = 0;
        for (std::int64_t s = ST[e]; s < ST[e + 1]; ++s) {
            if (!AL[TO[s]]) continue;
            const double* p = P + OP[s] * d;
            for (std::int64_t c = 0; c < d; ++c) sc.w[c] = p[c] - a[c];
            project(sc.w.data(), sc.q.data(), nq, d);
            const double norm = std::sqrt(dot(sc.w.data(), sc.w.data(), d)) + 1e-300;
            for (std::int64_t c = 0; c < d; ++c) sc.w[c] = sc.w[c] / norm;
            if (!got_ref) {
                sc.ref = sc.w;
                got_ref = true;
            } else if (!got_y) {
                const double c0 = dot(sc.w.data(), sc.ref.data(), d);
                for (std::int64_t c = 0; c < d; ++c) sc.wc[c] = sc.w[c] - c0 * sc.ref[c];  // yy
                const double ny = std::sqrt(dot(sc.wc.data(), sc.wc.data(), d));
                if (ny > 1e-9) {
                    for (std::int64_t c = 0; c < d; ++c) sc.y[c] = sc.wc[c] / ny;
                    got_y = true;
                }
            }
            ++cnt;
        }
        if (cnt == 0) continue;
        if (cnt == 1) {
            SH[e] = true;
            continue;
        }
        std::int64_t mm = 0;
        for (std::int64_t s = ST[e]; s < ST[e + 1]; ++s) {
            if (!AL[TO[s]] || mm >= 64) continue;
            const double* p = P + OP[s] * d;
            for (std::int64_t c = 0; c < d; ++c) sc.w[c] = p[c] - a[c];
            project(sc.w.data(), sc.q.data(), nq, d);
            angles[mm++] = py_fmod(std::atan2(dot(sc.w.data(), sc.y.data(), d), dot(sc.w.data(), sc.ref.data(), d)),
                                   TWO_PI);
        }
        std::sort(angles, angles + mm);  // finite values, zeros all +0: any sort gives the same array
        double gap = TWO_PI - angles[mm - 1] + angles[0];
        for (std::int64_t i = 1; i < mm; ++i) {
            const double gi = angles[i] - angles[i - 1];
            if (gi > gap) gap = gi;
        }
        if (gap > 1.5 * M_PI) SH[e] = true;
    }
}

// The walk's state of one ridge e of the oriented simplex: q (the ridge's basis), a (its first
// vertex) and wc, the unit direction of the vertex c opposite it, in the ridge's normal plane.
void ridge_frame(const Geom& g, const std::int64_t* ridge, std::int64_t c, Scratch& sc, const double*& a) {
    const std::int64_t d = g.d;
    complement_basis(g, ridge, sc.q.data());
    a = g.point(ridge[0]);
    const double* pc = g.point(c);
    for (std::int64_t x = 0; x < d; ++x) sc.wc[x] = pc[x] - a[x];
    project(sc.wc.data(), sc.q.data(), g.k1 - 2, d);
    const double norm = std::sqrt(dot(sc.wc.data(), sc.wc.data(), d)) + 1e-300;
    for (std::int64_t x = 0; x < d; ++x) sc.wc[x] = sc.wc[x] / norm;
}

// The turning angle in [0, 2π) about the ridge (frame in sc) from the oriented simplex to the
// vertex p: atan2(wd · nrm, wd · wc) with wd the direction of p in the ridge's normal plane.
double turning_angle(const Geom& g, const double* a, const double* p, Scratch& sc) {
    const std::int64_t d = g.d;
    for (std::int64_t x = 0; x < d; ++x) sc.w[x] = p[x] - a[x];
    project(sc.w.data(), sc.q.data(), g.k1 - 2, d);
    return py_fmod(std::atan2(dot(sc.w.data(), sc.nrm.data(), d), dot(sc.w.data(), sc.wc.data(), d)), TWO_PI);
}

// The ridges of the simplices and their incidences (crust_trimming.py's _ridge_structure): the ridges
// (R, n) as sorted rows, the ridge opposite each vertex of each simplex (ridge_of, (m, n + 1)), and
// per ridge r the simplices tri_of[start[r] .. start[r + 1] − 1] through it with their vertices opp
// opposite it.
struct Ridges {
    In<std::int64_t, nb::ndim<2>> ridges, ridge_of;
    In<std::int64_t, nb::ndim<1>> start, tri_of, opp;
};

// Coherently oriented walk from seed across every ridge to the next live simplex met when turning
// about the ridge through the outside (the side the oriented normal points to).  Depth first (a
// closed hypersurface), or breadth_first (a piece with boundary: the simplices near the seed are
// claimed before the walk reaches the debris along the boundary); a turn that folds by more than
// max_fold from flat is not taken.  Returns (orient (m, n + 1), visiting order, conflicts).
// Thesis: §3.4, "Triangulations" (the trimming of [ABK98]: the walk over the outside), Chapter 5.
std::tuple<Array<std::int64_t>, Array<std::int64_t>, std::int64_t> walk(
    In<double, nb::ndim<2>> pts, In<std::int64_t, nb::ndim<2>> simplices, In<bool, nb::ndim<1>> alive,
    const Ridges& structure, std::int64_t seed, bool seed_flip, bool breadth_first, double max_fold) {
    const Geom g = check_ridges("walk", pts, structure.ridges);
    const std::int64_t R = static_cast<std::int64_t>(structure.ridges.shape(0));
    check_simplices("walk", g, R, simplices, structure.ridge_of);
    const std::int64_t m = static_cast<std::int64_t>(simplices.shape(0)), k1 = g.k1, n = k1 - 1;
    check_incidence("walk", R, m, g.N, structure.start, structure.tri_of, structure.opp);
    if (static_cast<std::int64_t>(alive.shape(0)) != m) throw std::invalid_argument("walk: alive must have m entries");
    if (seed < 0 || seed >= m) throw std::invalid_argument("walk: seed is outside 0..m-1");
    const std::int64_t *S = simplices.data(), *RI = structure.ridges.data(), *RO = structure.ridge_of.data(),
                       *ST = structure.start.data(), *TO = structure.tri_of.data(), *OP = structure.opp.data();
    const bool* AL = alive.data();
    std::vector<std::int64_t> orient(static_cast<std::size_t>(m * k1), 0);
    std::vector<std::int64_t> visit;
    std::int64_t conflicts = 0;
    {
        nb::gil_scoped_release release;
        Scratch sc(g.d);
        std::vector<char> seen(static_cast<std::size_t>(m), 0);
        std::vector<std::int64_t> stack(static_cast<std::size_t>(m));
        visit.reserve(static_cast<std::size_t>(m));
        for (std::int64_t i = 0; i < k1; ++i) orient[seed * k1 + i] = S[seed * k1 + i];
        if (seed_flip) std::swap(orient[seed * k1], orient[seed * k1 + 1]);
        seen[seed] = 1;
        stack[0] = seed;
        std::int64_t top = 1, head = 0;
        std::vector<std::int64_t> o(k1), want(k1), rot(k1);
        while (top > head) {
            std::int64_t t;
            if (breadth_first) {
                t = stack[head++];
            } else {
                t = stack[--top];
            }
            visit.push_back(t);
            for (std::int64_t i = 0; i < k1; ++i) o[i] = orient[t * k1 + i];
            oriented_normal(g, o.data(), sc);
            for (std::int64_t j = 0; j < k1; ++j) {
                const std::int64_t pos_c = (j + n) % k1;  // positions n, 0, 1, ..., n - 1
                const std::int64_t c = o[pos_c];
                std::int64_t kc = 0;
                for (std::int64_t i = 0; i < k1; ++i)
                    if (S[t * k1 + i] == c) kc = i;
                const std::int64_t e = RO[t * k1 + kc];
                const double* a = nullptr;
                ridge_frame(g, RI + e * n, c, sc, a);
                std::int64_t best = -1, best_d = -1;
                double best_ang = 1e300;
                for (std::int64_t s = ST[e]; s < ST[e + 1]; ++s) {
                    const std::int64_t t2 = TO[s];
                    if (t2 == t || !AL[t2]) continue;
                    const double ang = turning_angle(g, a, g.point(OP[s]), sc);
                    if (ang < best_ang) {
                        best_ang = ang;
                        best = t2;
                        best_d = OP[s];
                    }
                }
                if (best < 0 || std::fabs(best_ang - M_PI) > max_fold) continue;
                // the ridge in cyclic order after c, then d; it must induce the opposite orientation
                for (std::int64_t i = 0; i < n; ++i) rot[i] = o[(pos_c + 1 + i) % k1];
                rot[n] = best_d;
                // [ridge, c] = sigma [o] with sigma the sign of a cyclic shift by pos_c + 1
                const int sigma = (n * (pos_c + 1)) % 2 == 1 ? -1 : 1;
                want = rot;
                if (sigma == 1) {  // want -[ridge, d]: one transposition (for n = 2: (b, a, d) across the edge a → b)
                    want[0] = rot[1];
                    want[1] = rot[0];
                }
                if (seen[best]) {
                    if (parity(want.data(), orient.data() + best * k1, k1) != 1) ++conflicts;
                    continue;
                }
                seen[best] = 1;
                for (std::int64_t i = 0; i < k1; ++i) orient[best * k1 + i] = want[i];
                if (top >= m) impossible("walk: stack overflow");
                stack[top++] = best;
            }
        }
    }
    const std::size_t mm = static_cast<std::size_t>(m), kk = static_cast<std::size_t>(k1);
    return {to_numpy(std::move(orient), {mm, kk}), to_numpy(std::move(visit)), conflicts};
}

// Keep simplices in visiting order while each of their ridges has fewer than two kept ones.
// Thesis: §3.4 (every edge of the reconstructed surface in at most two triangles).
Array<bool> greedy_manifold(In<std::int64_t, nb::ndim<2>> ridge_of, In<std::int64_t, nb::ndim<1>> order,
                            std::int64_t n_ridges) {
    const std::int64_t m = static_cast<std::int64_t>(ridge_of.shape(0)), k1 = static_cast<std::int64_t>(ridge_of.shape(1));
    const std::int64_t len = static_cast<std::int64_t>(order.shape(0));
    const std::int64_t *RO = ridge_of.data(), *OR = order.data();
    if (n_ridges < 0) throw std::invalid_argument("greedy_manifold: n_ridges must be non-negative");
    for (std::int64_t i = 0; i < m * k1; ++i)
        if (RO[i] < 0 || RO[i] >= n_ridges) throw std::invalid_argument("greedy_manifold: ridge_of is outside 0..n_ridges-1");
    for (std::int64_t i = 0; i < len; ++i)
        if (OR[i] < 0 || OR[i] >= m) throw std::invalid_argument("greedy_manifold: order is outside 0..m-1");
    bool* keep = new bool[len > 0 ? len : 1]();
    nb::capsule owner(keep, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> used(static_cast<std::size_t>(n_ridges), 0);
        for (std::int64_t i = 0; i < len; ++i) {
            const std::int64_t t = OR[i];
            bool ok = true;
            for (std::int64_t k = 0; k < k1; ++k)
                if (used[RO[t * k1 + k]] >= 2) ok = false;
            if (ok) {
                keep[i] = true;
                for (std::int64_t k = 0; k < k1; ++k) used[RO[t * k1 + k]] += 1;
            }
        }
    }
    std::size_t shape[1] = {static_cast<std::size_t>(len)};
    return Array<bool>(keep, 1, shape, owner);
}

// Smallest turning angle, over the ridges of simplex t (oriented, flipped or not), to another live
// simplex: about π on a sheet, small on the inner side of a pocket of candidates; one value per
// (ts[i], flips[i]).  Thesis: Chapter 5 (the seed of the open walk; the trimming of [ABK98], §3.4).
Array<double> openness(In<double, nb::ndim<2>> pts, In<std::int64_t, nb::ndim<2>> simplices, In<bool, nb::ndim<1>> alive,
                       const Ridges& structure, In<std::int64_t, nb::ndim<1>> ts, In<bool, nb::ndim<1>> flips) {
    const Geom g = check_ridges("openness", pts, structure.ridges);
    const std::int64_t R = static_cast<std::int64_t>(structure.ridges.shape(0));
    check_simplices("openness", g, R, simplices, structure.ridge_of);
    const std::int64_t m = static_cast<std::int64_t>(simplices.shape(0)), k1 = g.k1, n = k1 - 1;
    check_incidence("openness", R, m, g.N, structure.start, structure.tri_of, structure.opp);
    if (static_cast<std::int64_t>(alive.shape(0)) != m) throw std::invalid_argument("openness: alive must have m entries");
    const std::int64_t count = static_cast<std::int64_t>(ts.shape(0));
    if (static_cast<std::int64_t>(flips.shape(0)) != count)
        throw std::invalid_argument("openness: ts and flips must have the same length");
    const std::int64_t* TS = ts.data();
    for (std::int64_t i = 0; i < count; ++i)
        if (TS[i] < 0 || TS[i] >= m) throw std::invalid_argument("openness: t is outside 0..m-1");
    const std::int64_t *S = simplices.data(), *RI = structure.ridges.data(), *RO = structure.ridge_of.data(),
                       *ST = structure.start.data(), *TO = structure.tri_of.data(), *OP = structure.opp.data();
    const bool *AL = alive.data(), *FL = flips.data();
    std::vector<double> out(static_cast<std::size_t>(count));
    {
        nb::gil_scoped_release release;
        Scratch sc(g.d);
        std::vector<std::int64_t> o(k1);
        for (std::int64_t it = 0; it < count; ++it) {
            const std::int64_t t = TS[it];
            for (std::int64_t i = 0; i < k1; ++i) o[i] = S[t * k1 + i];
            if (FL[it]) std::swap(o[0], o[1]);
            oriented_normal(g, o.data(), sc);
            double worst = TWO_PI;
            for (std::int64_t kc = 0; kc < k1; ++kc) {
                const std::int64_t e = RO[t * k1 + kc];
                const double* a = nullptr;
                ridge_frame(g, RI + e * n, S[t * k1 + kc], sc, a);
                for (std::int64_t s = ST[e]; s < ST[e + 1]; ++s) {
                    if (TO[s] == t || !AL[TO[s]]) continue;
                    const double ang = turning_angle(g, a, g.point(OP[s]), sc);
                    if (ang < worst) worst = ang;
                }
            }
            out[it] = worst;
        }
    }
    return to_numpy(std::move(out));
}

}  // namespace thesis

NB_MODULE(crust_trimming, m) {
    namespace nb = nanobind;
    m.doc() = "The trimming step of the Crust: sharp ridges, the outer walk, the greedy manifold (thesis §3.4).";
    m.def("sharp_ridges", &thesis::sharp_ridges, nb::arg("pts"), nb::arg("ridges"), nb::arg("alive"), nb::arg("start"),
          nb::arg("tri_of"), nb::arg("opp"), nb::arg("todo"), nb::arg("sharp"));
    nb::class_<thesis::Ridges>(m, "Ridges", "The ridges of the simplices and their incidences (_ridge_structure).")
        .def(nb::init<thesis::In<std::int64_t, nb::ndim<2>>, thesis::In<std::int64_t, nb::ndim<2>>,
                      thesis::In<std::int64_t, nb::ndim<1>>, thesis::In<std::int64_t, nb::ndim<1>>,
                      thesis::In<std::int64_t, nb::ndim<1>>>(),
             nb::arg("ridges"), nb::arg("ridge_of"), nb::arg("start"), nb::arg("tri_of"), nb::arg("opp"));
    m.def("walk", &thesis::walk, nb::arg("pts"), nb::arg("simplices"), nb::arg("alive"), nb::arg("structure"),
          nb::arg("seed"), nb::arg("seed_flip"), nb::arg("breadth_first"), nb::arg("max_fold"));
    m.def("greedy_manifold", &thesis::greedy_manifold, nb::arg("ridge_of"), nb::arg("order"), nb::arg("n_ridges"));
    m.def("openness", &thesis::openness, nb::arg("pts"), nb::arg("simplices"), nb::arg("alive"), nb::arg("structure"),
          nb::arg("ts"), nb::arg("flips"));
}
