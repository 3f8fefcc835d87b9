// Vertex areas of a triangle mesh: the Voronoi and mixed regions of §3.3.2.
#include "arrays.hpp"

namespace thesis {

// Vertex areas of a triangle mesh from the validated corner data, in one pass: corner k gets
// 1/8 (cot_{k+1} |e_{k+1}|² + cot_{k+2} |e_{k+2}|²), cot_j = dot_j / (2 area); with mixed, an obtuse
// triangle gives its obtuse corner half its area and the other two a quarter each (Meyer et al.).
// Thesis: §3.3.2 (Voronoi and barycentric regions), Figure 3.4.
Array<double> triangle_areas(In<std::int64_t, nb::ndim<2>> s, In<double, nb::ndim<2>> dot,
                             In<double, nb::ndim<2>> edge_sq, In<double, nb::ndim<1>> twice,
                             std::int64_t nv, bool mixed) {
    const std::size_t m = s.shape(0);
    if (s.shape(1) != 3) throw std::invalid_argument("triangle_areas: s must have shape (m, 3)");
    if (dot.shape(0) != 3 || dot.shape(1) != m || edge_sq.shape(0) != 3 || edge_sq.shape(1) != m)
        throw std::invalid_argument("triangle_areas: dot and edge_sq must have shape (3, m)");
    if (twice.shape(0) != m) throw std::invalid_argument("triangle_areas: twice must have shape (m,)");
    if (nv < 0) throw std::invalid_argument("triangle_areas: nv must be non-negative");
    std::vector<double> out(static_cast<std::size_t>(nv), 0.0);
    // raw C-order pointers: s (m, 3); dot, edge_sq (3, m) corner-major
    const std::int64_t* S = s.data();
    const double *D = dot.data(), *E = edge_sq.data(), *TW = twice.data();
    bool bad_index = false;
    {
        nb::gil_scoped_release release;
        for (std::size_t t = 0; t < m; ++t) {
            const std::int64_t i0 = S[3 * t], i1 = S[3 * t + 1], i2 = S[3 * t + 2];
            if (i0 < 0 || i0 >= nv || i1 < 0 || i1 >= nv || i2 < 0 || i2 >= nv) {  // checked before any write
                bad_index = true;
                break;
            }
            const double tw = TW[t];
            const double d0 = D[t], d1 = D[m + t], d2 = D[2 * m + t];
            if (mixed && (d0 < 0 || d1 < 0 || d2 < 0)) {
                out[i0] += d0 < 0 ? 0.25 * tw : 0.125 * tw;
                out[i1] += d1 < 0 ? 0.25 * tw : 0.125 * tw;
                out[i2] += d2 < 0 ? 0.25 * tw : 0.125 * tw;
                continue;
            }
            const double w0 = d0 / tw * E[t];
            const double w1 = d1 / tw * E[m + t];
            const double w2 = d2 / tw * E[2 * m + t];
            out[i0] += 0.125 * (w1 + w2);
            out[i1] += 0.125 * (w2 + w0);
            out[i2] += 0.125 * (w0 + w1);
        }
    }
    if (bad_index) throw std::invalid_argument("triangle_areas: a vertex index is outside 0..nv-1");
    return to_numpy(std::move(out));
}

}  // namespace thesis

NB_MODULE(vertex_areas, m) {
    m.doc() = "Vertex areas of triangle meshes (thesis §3.3.2).";
    m.def("triangle_areas", &thesis::triangle_areas, nanobind::arg("s"), nanobind::arg("dot"),
          nanobind::arg("edge_sq"), nanobind::arg("twice"), nanobind::arg("nv"), nanobind::arg("mixed"));
}
