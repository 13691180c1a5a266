// Dense numbers for 64-bit node keys (chaining's edge and vertex keys), each within a 32-bit
// key space (LineSegment::isoline: the same edge key on two isolines is two nodes): a flat table
// with open addressing, about five times faster than std::unordered_map for the 10^5 keys of a
// view's lines, and the numbering (0, 1, 2, … in order of first insertion) does not depend on
// the hash.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace inkshade::geometry {

// Fibonacci hashing (Knuth, TAOCP vol. 3, §6.4): neighbouring keys (the edges of one face)
// land far apart. `bits` is the table's log2 size.
inline size_t fibonacci_slot(uint64_t key, uint32_t space, int bits) {
    // The space is mixed in by a second odd multiplier, so (key, space) pairs spread as keys do.
    const uint64_t hash = key * 0x9e3779b97f4a7c15ull + uint64_t(space) * 0xc2b2ae3d27d4eb4full;
    return size_t((hash ^ (hash >> 29)) >> (64 - bits));
}

class KeyNumbering {
public:
    // Room for `expected` keys at most half full; more keys are still taken (the table grows).
    explicit KeyNumbering(size_t expected) { rehash(std::bit_width(std::max<size_t>(2 * expected, 16) - 1)); }

    // The number of `key` in key space `space`; a pair not seen before gets size().
    uint32_t insert(uint64_t key, uint32_t space = 0) {
        for (size_t h = fibonacci_slot(key, space, bits_);; h = (h + 1) & mask_) {
            Slot& s = slots_[h];
            if (s.number == kEmpty) {
                s = {key, count_, space};
                if (++count_ * 2 > slots_.size()) rehash(bits_ + 1);
                return count_ - 1;
            }
            if (s.key == key && s.space == space) return s.number;
        }
    }
    uint32_t size() const { return count_; }

private:
    static constexpr uint32_t kEmpty = 0xffffffffu;
    struct Slot {
        uint64_t key = 0;
        uint32_t number = kEmpty;
        uint32_t space = 0;  // fills the padding: still 16 bytes a slot
    };

    void rehash(int bits) {
        std::vector<Slot> old = std::move(slots_);
        bits_ = bits;
        slots_.assign(size_t(1) << bits, Slot{});
        mask_ = slots_.size() - 1;
        for (const Slot& s : old)
            if (s.number != kEmpty) {
                size_t h = fibonacci_slot(s.key, s.space, bits_);
                while (slots_[h].number != kEmpty) h = (h + 1) & mask_;
                slots_[h] = s;
            }
    }

    std::vector<Slot> slots_;
    int bits_ = 0;
    size_t mask_ = 0;
    uint32_t count_ = 0;
};

}  // namespace inkshade::geometry
