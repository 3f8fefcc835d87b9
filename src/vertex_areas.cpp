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
    const std::int64_t* sp = s.data();
    for (std::size_t i = 0; i < 3 * m; ++i)
        if (sp[i] < 0 || sp[i] >= nv) throw std::invalid_argument("triangle_areas: a vertex index is outside 0..nv-1");
    std::vector<double> out(static_cast<std::size_t>(nv), 0.0);
    const auto S = s.view();
    const auto D = dot.view(), E = edge_sq.view();
    const auto tw2 = twice.view();
    {
        nb::gil_scoped_release release;
        for (std::size_t t = 0; t < m; ++t) {
            const double tw = tw2(t);
            if (mixed && (D(0, t) < 0 || D(1, t) < 0 || D(2, t) < 0)) {
                for (std::size_t k = 0; k < 3; ++k) out[S(t, k)] += D(k, t) < 0 ? 0.25 * tw : 0.125 * tw;
                continue;
            }
            const double w0 = D(0, t) / tw * E(0, t);
            const double w1 = D(1, t) / tw * E(1, t);
            const double w2 = D(2, t) / tw * E(2, t);
            out[S(t, 0)] += 0.125 * (w1 + w2);
            out[S(t, 1)] += 0.125 * (w2 + w0);
            out[S(t, 2)] += 0.125 * (w0 + w1);
        }
    }
    return to_numpy(std::move(out));
}

}  // namespace thesis

NB_MODULE(vertex_areas, m) {
    m.doc() = "Vertex areas of triangle meshes (thesis §3.3.2).";
    m.def("triangle_areas", &thesis::triangle_areas, nanobind::arg("s"), nanobind::arg("dot"),
          nanobind::arg("edge_sq"), nanobind::arg("twice"), nanobind::arg("nv"), nanobind::arg("mixed"));
}
