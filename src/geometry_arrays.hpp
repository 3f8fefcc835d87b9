// Arrays shared by the exact-geometry kernels (predicate filters, miniball, triangulation, alpha):
// boolean NumPy outputs (std::vector<bool> has no contiguous storage) and the index checks at entry.
#pragma once

#include "arrays.hpp"

#include <memory>
#include <string>

namespace thesis {

// A zeroed (all False) buffer of n bools for a kernel to fill (also with the GIL released).
inline std::unique_ptr<bool[]> bool_buffer(std::size_t n) { return std::unique_ptr<bool[]>(new bool[n > 0 ? n : 1]()); }

// A new one-dimensional NumPy bool array of n entries owning the buffer (call with the GIL held).
inline Array<bool> to_numpy(std::unique_ptr<bool[]>&& data, std::size_t n) {
    bool* raw = data.release();
    nb::capsule owner(raw, [](void* p) noexcept { delete[] static_cast<bool*>(p); });
    std::size_t shape[1] = {n};
    return Array<bool>(raw, 1, shape, owner);
}

// Throws ValueError unless every one of the `count` indices at `p` lies in [0, n).
inline void check_indices(const std::int64_t* p, std::size_t count, std::size_t n, const char* what) {
    for (std::size_t i = 0; i < count; ++i) {
        if (p[i] < 0 || static_cast<std::uint64_t>(p[i]) >= n) {
            throw std::invalid_argument(std::string(what) + ": index " + std::to_string(p[i]) + " out of range [0, " +
                                        std::to_string(n) + ")");
        }
    }
}

// Throws ValueError unless `got` equals `want` (a shape check at a kernel's entry).
inline void check_size(std::size_t got, std::size_t want, const char* what) {
    if (got != want) {
        throw std::invalid_argument(std::string(what) + ": expected " + std::to_string(want) + ", got " +
                                    std::to_string(got));
    }
}

}  // namespace thesis
