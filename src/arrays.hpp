// NumPy arrays in and out of the compiled kernels, and the integer arithmetic of Python.
//
// Every kernel takes its arrays as nanobind views of C-contiguous CPU NumPy arrays (the Python layer
// validates and casts before calling: a kernel trusts its input) and returns new arrays that own
// their memory.  Integer division and remainder follow Python's floor convention, as the kernels'
// numba originals did; a kernel that meets an impossible state throws (a Python RuntimeError).
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace thesis {

namespace nb = nanobind;

// Read-only and writable views of C-contiguous NumPy arrays of element type T.
template <class T, class... Extra>
using In = nb::ndarray<const T, nb::numpy, nb::c_contig, nb::device::cpu, Extra...>;
template <class T, class... Extra>
using Out = nb::ndarray<T, nb::numpy, nb::c_contig, nb::device::cpu, Extra...>;
template <class T>
using Array = nb::ndarray<nb::numpy, T>;

// A new NumPy array owning the vector's memory, of the given shape (the product must be v.size()).
template <class T>
Array<T> to_numpy(std::vector<T>&& v, std::initializer_list<std::size_t> shape) {
    std::size_t count = 1;
    for (std::size_t s : shape) count *= s;
    if (count != v.size()) throw std::logic_error("to_numpy: shape does not match the data");
    auto* owned = new std::vector<T>(std::move(v));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
    return Array<T>(owned->data(), shape.size(), shape.begin(), owner);
}

// A new one-dimensional NumPy array owning the vector's memory.
template <class T>
Array<T> to_numpy(std::vector<T>&& v) {
    std::size_t n = v.size();
    return to_numpy(std::move(v), {n});
}

// Python's a // b and a % b (floor division) for b != 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
    return q;
}
inline std::int64_t floor_mod(std::int64_t a, std::int64_t b) {
    std::int64_t r = a % b;
    if (r != 0 && ((r < 0) != (b < 0))) r += b;
    return r;
}

// The number of threads a parallel kernel uses: n_threads when positive, else OMP_NUM_THREADS when
// set to a positive integer, else the hardware's count (at least 1).
inline int thread_count(int n_threads) {
    if (n_threads > 0) return n_threads;
    if (const char* env = std::getenv("OMP_NUM_THREADS")) {
        char* end = nullptr;
        long v = std::strtol(env, &end, 10);
        if (end != env && v > 0) return static_cast<int>(v);
    }
    unsigned hw = std::thread::hardware_concurrency();
    return hw > 0 ? static_cast<int>(hw) : 1;
}

// Raised by a kernel that meets a state its validated input cannot produce.
[[noreturn]] inline void impossible(const std::string& what) {
    throw std::runtime_error("thesis_lib internal error: " + what);
}

}  // namespace thesis
