// The field arithmetic and the working column shared by every persistence reduction.
//
// A working column of a reduction is a binary min-heap of entries (value, key, coefficient) ordered
// by (value, key): the pivot of the column is its least entry whose coefficients (entries of the same
// key are summed lazily, as in Ripser) do not cancel mod p.  Used by the stored-matrix reduction
// (reduction.cpp) and the implicit Rips engine (implicit_rips.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace thesis {

// a^-1 in Z/p by the extended Euclidean algorithm; p < 2^31 so that products fit in int64.
// Thesis: Algorithm 1 (Reduce), the factor q^-1 of d = d - q^-1 T[i].
inline std::int64_t mod_inverse(std::int64_t a, std::int64_t p) {
    std::int64_t t = 0, newt = 1, r = p, newr = ((a % p) + p) % p;
    while (newr != 0) {
        const std::int64_t q = r / newr;
        std::int64_t tmp = t - q * newt;
        t = newt;
        newt = tmp;
        tmp = r - q * newr;
        r = newr;
        newr = tmp;
    }
    return ((t % p) + p) % p;
}

// The least entry of a column whose summed coefficient is non-zero mod p; coef 0 (value +inf, key 0)
// when the column is zero.
template <class V, class K, class C>
struct Pivot {
    V value;
    K key;
    C coef;
};

// A binary min-heap of entries (value, key, coefficient) ordered by (value, key), held in three
// parallel arrays that grow as needed.
// Thesis: §2.3.5, the column of Algorithm 1 being reduced (summed lazily, as in Bauer 2021).
template <class V, class K, class C>
class ColumnHeap {
  public:
    std::vector<V> value;
    std::vector<K> key;
    std::vector<C> coef;
    std::int64_t size = 0;

    explicit ColumnHeap(std::size_t capacity = 1024) : value(capacity), key(capacity), coef(capacity) {}

    bool empty() const { return size == 0; }
    void clear() { size = 0; }

    // Room for need entries in all (the first size kept): the capacity doubles when too small.
    void reserve(std::int64_t need) {
        std::size_t cap = value.size() ? value.size() : 1;
        if (static_cast<std::size_t>(need) <= value.size()) return;
        while (cap < static_cast<std::size_t>(need)) cap *= 2;
        value.resize(cap);
        key.resize(cap);
        coef.resize(cap);
    }

    // Push (v, k, c).
    void push(V v, K k, C c) {
        reserve(size + 1);
        std::int64_t i = size;
        while (i > 0) {
            const std::int64_t par = (i - 1) >> 1;
            if (v < value[par] || (v == value[par] && k < key[par])) {
                put(i, value[par], key[par], coef[par]);
                i = par;
            } else {
                break;
            }
        }
        put(i, v, k, c);
        ++size;
    }

    // Remove the top entry (read it first).
    void pop() {
        --size;
        if (size > 0) replace_top(value[size], key[size], coef[size]);
    }

    // Replace the top entry by (v, k, c) and restore the order (one sift-down).
    void replace_top(V v, K k, C c) {
        std::int64_t i = 0;
        for (;;) {
            const std::int64_t left = 2 * i + 1;
            if (left >= size) break;
            std::int64_t m = left;
            const std::int64_t right = left + 1;
            if (right < size && (value[right] < value[left] || (value[right] == value[left] && key[right] < key[left])))
                m = right;
            if (value[m] < v || (value[m] == v && key[m] < k)) {
                put(i, value[m], key[m], coef[m]);
                i = m;
            } else {
                break;
            }
        }
        put(i, v, k, c);
    }

    // Pop entries until the least key whose summed coefficient is non-zero mod p (removed from the
    // heap: a caller adding a column with the same pivot skips that column's pivot entries).
    Pivot<V, K, C> pop_pivot(std::int64_t p) {
        while (size > 0) {
            const V v = value[0];
            const K k = key[0];
            std::int64_t c = coef[0];
            pop();
            while (size > 0 && key[0] == k && value[0] == v) {
                c += coef[0];
                pop();
            }
            c %= p;
            if (c != 0) return {v, k, static_cast<C>(c)};
        }
        return {std::numeric_limits<V>::infinity(), K(0), C(0)};
    }

  private:
    void put(std::int64_t i, V v, K k, C c) {
        value[i] = v;
        key[i] = k;
        coef[i] = c;
    }
};

// The distinct keys of keys[0..n) with their coefficients summed mod p, zeros dropped: for each
// surviving key (increasing) the first position holding it and its sum.  Stores a reduction chain V.
// Thesis: §2.3.5 (the chain V of R = D V, kept for the columns a later column may add).
template <class K, class C>
void merge_entries(const K* keys, const C* coefs, std::int64_t n, std::int64_t p, std::vector<std::int64_t>& pos,
                   std::vector<std::int64_t>& sums) {
    std::vector<std::int64_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [keys](std::int64_t a, std::int64_t b) { return keys[a] < keys[b]; });
    pos.clear();
    sums.clear();
    std::int64_t i = 0;
    while (i < n) {
        const std::int64_t first = order[i];
        std::int64_t c = 0;
        while (i < n && keys[order[i]] == keys[first]) {
            c += coefs[order[i]];
            ++i;
        }
        c %= p;
        if (c != 0) {
            pos.push_back(first);
            sums.push_back(c);
        }
    }
}

}  // namespace thesis
