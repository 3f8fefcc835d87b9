// Simplicial pseudo-manifolds: the combinatorial condition the curvature estimates of §3.3 need.
#include "arrays.hpp"
#include "union_find.hpp"

#include <nanobind/stl/tuple.h>

#include <algorithm>
#include <memory>
#include <tuple>

namespace thesis {

// A new NumPy bool array of n entries, all false.
inline nb::ndarray<nb::numpy, bool> bool_array(std::size_t n, bool*& data) {
    data = new bool[n > 0 ? n : 1]();
    nb::capsule owner(data, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    std::size_t shape[1] = {n};
    return nb::ndarray<nb::numpy, bool>(data, 1, shape, owner);
}

using BoolArray = nb::ndarray<nb::numpy, bool>;

// (code, a, b, c, pinched, boundary): 0 ok; 1 simplices a, b repeat; 2 ridge (a without b) in 3+
// simplices; 3 vertex a pinched between simplices b and c (the first of the pinched mask); boundary
// marks the vertices of the ridges in one simplex.  Ridge r = (simplex r // k without its local
// vertex r % k) has smallest vertex lo[r] and the others encoded injectively in key[r]: ridges are
// bucketed by lo, sorted by key within a bucket (stable), and the corners of two simplices sharing a
// ridge are joined in a union–find; a vertex whose corners fall in two classes is pinched.
// Thesis: §3.3 (the estimates sum over the star of a vertex, one fan) and §3.1.2.
std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t, BoolArray, BoolArray> pseudomanifold_kernel(
    In<std::int64_t, nb::ndim<2>> s, In<std::int64_t, nb::ndim<1>> lo, In<std::int64_t, nb::ndim<1>> key,
    std::int64_t nv, bool check_links) {
    const std::int64_t m = static_cast<std::int64_t>(s.shape(0));
    const std::int64_t k = static_cast<std::int64_t>(s.shape(1));
    const std::int64_t mk = m * k;
    if (nv < 0) throw std::invalid_argument("pseudomanifold_kernel: nv must be non-negative");
    if (k < 1 && m > 0) throw std::invalid_argument("pseudomanifold_kernel: s must have shape (m, k) with k >= 1");
    if (static_cast<std::int64_t>(lo.shape(0)) != mk || static_cast<std::int64_t>(key.shape(0)) != mk)
        throw std::invalid_argument("pseudomanifold_kernel: lo and key must have m * k entries");
    const std::int64_t* S = s.data();
    const std::int64_t* LO = lo.data();
    const std::int64_t* KEY = key.data();
    for (std::int64_t i = 0; i < mk; ++i) {
        if (S[i] < 0 || S[i] >= nv) throw std::invalid_argument("pseudomanifold_kernel: a vertex index is outside 0..nv-1");
        if (LO[i] < 0 || LO[i] >= nv) throw std::invalid_argument("pseudomanifold_kernel: lo is outside 0..nv-1");
    }
    bool* boundary = nullptr;
    bool* pinched = nullptr;
    BoolArray boundary_arr = bool_array(static_cast<std::size_t>(nv), boundary);
    BoolArray pinched_arr = bool_array(static_cast<std::size_t>(nv), pinched);
    std::int64_t code = 0, a = 0, b = 0, c = 0;
    {
        nb::gil_scoped_release release;
        std::vector<std::int64_t> counts(static_cast<std::size_t>(nv) + 1, 0);
        for (std::int64_t r = 0; r < mk; ++r) counts[LO[r] + 1] += 1;
        for (std::int64_t v = 0; v < nv; ++v) counts[v + 1] += counts[v];
        std::vector<std::int64_t> fill(counts.begin(), counts.end() - 1);
        std::unique_ptr<std::int64_t[]> entries(new std::int64_t[mk > 0 ? mk : 1]);  // every slot written below
        for (std::int64_t r = 0; r < mk; ++r) entries[fill[LO[r]]++] = r;
        std::unique_ptr<std::int64_t[]> parent(new std::int64_t[mk > 0 ? mk : 1]);
        for (std::int64_t r = 0; r < mk; ++r) parent[r] = r;
        for (std::int64_t v = 0; v < nv && code == 0; ++v) {
            const std::int64_t start = counts[v], end = counts[v + 1];
            const std::int64_t size = end - start;
            if (size == 0) continue;
            std::int64_t* bucket = entries.get() + start;
            if (size <= 32) {  // insertion sort by key (buckets hold a vertex's few ridges on meshes)
                for (std::int64_t x = 1; x < size; ++x) {
                    const std::int64_t cur = bucket[x];
                    std::int64_t y = x - 1;
                    while (y >= 0 && KEY[bucket[y]] > KEY[cur]) {
                        bucket[y + 1] = bucket[y];
                        --y;
                    }
                    bucket[y + 1] = cur;
                }
            } else {  // the stable order of np.argsort(kind="mergesort")
                std::stable_sort(bucket, bucket + size,
                                 [&](std::int64_t p, std::int64_t q) { return KEY[p] < KEY[q]; });
            }
            std::int64_t x = 0;
            while (x < size) {
                std::int64_t y = x + 1;
                while (y < size && KEY[bucket[y]] == KEY[bucket[x]]) ++y;
                const std::int64_t run = y - x;
                if (run > 2) {
                    code = 2, a = bucket[x] / k, b = bucket[x] % k, c = 0;
                    break;
                }
                if (run == 1) {  // a boundary ridge
                    const std::int64_t t1 = bucket[x] / k, i1 = bucket[x] % k;
                    for (std::int64_t j1 = 0; j1 < k; ++j1)
                        if (j1 != i1) boundary[S[t1 * k + j1]] = true;
                }
                if (run == 2) {
                    const std::int64_t t1 = bucket[x] / k, i1 = bucket[x] % k;
                    const std::int64_t t2 = bucket[x + 1] / k, i2 = bucket[x + 1] % k;
                    if (S[t1 * k + i1] == S[t2 * k + i2]) {
                        code = 1, a = std::min(t1, t2), b = std::max(t1, t2), c = 0;
                        break;
                    }
                    // glue the corners of the two simplices at each vertex of the common ridge
                    for (std::int64_t j1 = 0; j1 < k; ++j1) {
                        if (j1 == i1) continue;
                        for (std::int64_t j2 = 0; j2 < k; ++j2) {
                            if (S[t2 * k + j2] == S[t1 * k + j1]) {
                                const std::int64_t ra = find(parent.get(), t1 * k + j1);
                                const std::int64_t rb = find(parent.get(), t2 * k + j2);
                                if (ra != rb) parent[ra] = rb;
                            }
                        }
                    }
                }
                x = y;
            }
        }
        if (code == 0 && check_links) {
            std::vector<std::int64_t> first(static_cast<std::size_t>(nv), -1), where(static_cast<std::size_t>(nv), -1);
            for (std::int64_t t = 0; t < m; ++t) {
                for (std::int64_t j = 0; j < k; ++j) {
                    const std::int64_t v = S[t * k + j];
                    const std::int64_t r = find(parent.get(), t * k + j);
                    if (first[v] < 0) {
                        first[v] = r;
                        where[v] = t;
                    } else if (first[v] != r && !pinched[v]) {
                        pinched[v] = true;
                        if (code == 0) code = 3, a = v, b = where[v], c = t;
                    }
                }
            }
        }
    }
    if (code == 1 || code == 2) return {code, a, b, c, boundary_arr, boundary_arr};  // as the original
    return {code, a, b, c, pinched_arr, boundary_arr};
}

}  // namespace thesis

NB_MODULE(pseudomanifold, m) {
    namespace nb = nanobind;
    m.doc() = "The pseudo-manifold check of triangulated hypersurfaces (thesis §3.3).";
    m.def("pseudomanifold_kernel", &thesis::pseudomanifold_kernel, nb::arg("s"), nb::arg("lo"), nb::arg("key"),
          nb::arg("nv"), nb::arg("check_links"));
}
