// The corner data of triangle meshes in R³: the Gram entries and cotangents of §3.3.
#include "arrays.hpp"

#include <nanobind/stl/tuple.h>

#include <cmath>
#include <tuple>

namespace thesis {

// Python's max(a, b, ...) on floats: the first of the largest (a later value replaces only when >).
inline double py_max(double a, double b) { return b > a ? b : a; }

// The corner data of m triangles, filled by triangle_kernel: the Gram entries dot (3, m) and squared
// edges sq (3, m) at each corner, twice the areas (m,), the corners' coordinates pts (3, 3, m), and the
// ends lo < hi (m, 3) of the edge opposite each corner.
struct Corners {
    Out<double, nb::ndim<2>> dot, sq;
    Out<double, nb::ndim<1>> twice;
    Out<double, nb::ndim<3>> pts;
    Out<std::int64_t, nb::ndim<2>> lo, hi;
};

// Fill the corner data out (dot, sq, twice, pts, lo, hi) of the triangles s (m, 3) of the vertices
// v (nv, 3); return (first simplex with a repeated vertex, first
// degenerate one, number of degenerate ones, longest squared edge), -1 for none (degenerate: area
// <= rtol * longest edge², as in validate_mesh).
// Thesis: Theorem 3.18 and §3.3.2 (the Gram matrices and corner cotangents of triangles).
std::tuple<std::int64_t, std::int64_t, std::int64_t, double> triangle_kernel(
    In<double, nb::ndim<2>> v, In<std::int64_t, nb::ndim<2>> s, const Corners& out, double rtol) {
    const Out<double, nb::ndim<2>>& dot = out.dot;
    const Out<double, nb::ndim<2>>& sq = out.sq;
    const Out<double, nb::ndim<1>>& twice = out.twice;
    const Out<double, nb::ndim<3>>& pts = out.pts;
    const Out<std::int64_t, nb::ndim<2>>& lo = out.lo;
    const Out<std::int64_t, nb::ndim<2>>& hi = out.hi;
    const std::size_t m = s.shape(0);
    const std::int64_t nv = static_cast<std::int64_t>(v.shape(0));
    if (v.shape(1) != 3) throw std::invalid_argument("triangle_kernel: v must have shape (nv, 3)");
    if (s.shape(1) != 3) throw std::invalid_argument("triangle_kernel: s must have shape (m, 3)");
    if (dot.shape(0) != 3 || dot.shape(1) != m || sq.shape(0) != 3 || sq.shape(1) != m)
        throw std::invalid_argument("triangle_kernel: dot and sq must have shape (3, m)");
    if (twice.shape(0) != m) throw std::invalid_argument("triangle_kernel: twice must have shape (m,)");
    if (pts.shape(0) != 3 || pts.shape(1) != 3 || pts.shape(2) != m)
        throw std::invalid_argument("triangle_kernel: pts must have shape (3, 3, m)");
    if (lo.shape(0) != m || lo.shape(1) != 3 || hi.shape(0) != m || hi.shape(1) != 3)
        throw std::invalid_argument("triangle_kernel: lo and hi must have shape (m, 3)");
    const std::int64_t* sp = s.data();
    for (std::size_t i = 0; i < 3 * m; ++i)
        if (sp[i] < 0 || sp[i] >= nv) throw std::invalid_argument("triangle_kernel: a vertex index is outside 0..nv-1");
    // raw C-order pointers: dot, sq (3, m) corner-major; pts (3, 3, m); lo, hi (m, 3)
    const double* V = v.data();
    double *D = dot.data(), *Q = sq.data(), *T = twice.data(), *P = pts.data();
    std::int64_t *L = lo.data(), *H = hi.data();
    std::int64_t first_repeated = -1, first_degenerate = -1, n_degenerate = 0;
    double longest = 0.0;
    {
        nb::gil_scoped_release release;
        for (std::size_t t = 0; t < m; ++t) {
            const std::int64_t* st = sp + 3 * t;
            if (first_repeated < 0 && (st[0] == st[1] || st[1] == st[2] || st[0] == st[2]))
                first_repeated = static_cast<std::int64_t>(t);
            const std::int64_t i0 = st[0], i1 = st[1], i2 = st[2];
            // the edge opposite corner k is ridge 3t + k: (1, 2), (2, 0), (0, 1), as (min, max)
            L[3 * t] = i1 < i2 ? i1 : i2;
            H[3 * t] = i1 > i2 ? i1 : i2;
            L[3 * t + 1] = i2 < i0 ? i2 : i0;
            H[3 * t + 1] = i2 > i0 ? i2 : i0;
            L[3 * t + 2] = i0 < i1 ? i0 : i1;
            H[3 * t + 2] = i0 > i1 ? i0 : i1;
            const double* v0 = V + 3 * i0;
            const double* v1 = V + 3 * i1;
            const double* v2 = V + 3 * i2;
            const double c[3][3] = {{v0[0], v0[1], v0[2]}, {v1[0], v1[1], v1[2]}, {v2[0], v2[1], v2[2]}};
            for (std::size_t k = 0; k < 3; ++k) {  // pts[k, a, t]
                P[(3 * k) * m + t] = c[k][0];
                P[(3 * k + 1) * m + t] = c[k][1];
                P[(3 * k + 2) * m + t] = c[k][2];
            }
            // edge opposite corner k: e0 = p2 - p1, e1 = p0 - p2, e2 = p1 - p0
            const double e0x = c[2][0] - c[1][0], e0y = c[2][1] - c[1][1], e0z = c[2][2] - c[1][2];
            const double e1x = c[0][0] - c[2][0], e1y = c[0][1] - c[2][1], e1z = c[0][2] - c[2][2];
            const double e2x = c[1][0] - c[0][0], e2y = c[1][1] - c[0][1], e2z = c[1][2] - c[0][2];
            const double s0 = e0x * e0x + e0y * e0y + e0z * e0z;
            const double s1 = e1x * e1x + e1y * e1y + e1z * e1z;
            const double s2 = e2x * e2x + e2y * e2y + e2z * e2z;
            Q[t] = s0;
            Q[m + t] = s1;
            Q[2 * m + t] = s2;
            longest = py_max(py_max(py_max(longest, s0), s1), s2);
            D[t] = 0.5 * (s1 + s2 - s0);  // law of cosines
            D[m + t] = 0.5 * (s2 + s0 - s1);
            D[2 * m + t] = 0.5 * (s0 + s1 - s2);
            const double cx = e1y * e2z - e1z * e2y;
            const double cy = e1z * e2x - e1x * e2z;
            const double cz = e1x * e2y - e1y * e2x;
            const double tw = std::sqrt(cx * cx + cy * cy + cz * cz);
            T[t] = tw;
            if (0.5 * tw <= rtol * py_max(py_max(s0, s1), s2)) {
                ++n_degenerate;
                if (first_degenerate < 0) first_degenerate = static_cast<std::int64_t>(t);
            }
        }
    }
    return {first_repeated, first_degenerate, n_degenerate, longest};
}

}  // namespace thesis

NB_MODULE(triangle_geometry, m) {
    namespace nb = nanobind;
    m.doc() = "Corner data of triangle meshes in R^3 (thesis Theorem 3.18, §3.3.2).";
    using thesis::Out;
    nb::class_<thesis::Corners>(m, "Corners", "The corner data of m triangles that triangle_kernel fills.")
        .def(nb::init<Out<double, nb::ndim<2>>, Out<double, nb::ndim<2>>, Out<double, nb::ndim<1>>,
                      Out<double, nb::ndim<3>>, Out<std::int64_t, nb::ndim<2>>, Out<std::int64_t, nb::ndim<2>>>(),
             nb::arg("dot"), nb::arg("sq"), nb::arg("twice"), nb::arg("pts"), nb::arg("lo"), nb::arg("hi"));
    m.def("triangle_kernel", &thesis::triangle_kernel, nb::arg("v"), nb::arg("s"), nb::arg("out"), nb::arg("rtol"));
}
