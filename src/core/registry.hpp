// The registries of named things that register themselves from the file that implements them
// (line types, shading models, render passes), so adding one touches nothing else: one
// registration, lookup by name, listing in order and the "unknown X 'name'" error for all.
// Entries are added during static initialisation (a function-local static Registry each, so
// that it exists before the first registration) and only read afterwards.
#pragma once
#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"

namespace inkshade {

// T has a std::string `name`: lower case, unique in its registry even ignoring case.
template <class T>
class Registry {
public:
    // Whether a is listed before b; the registration order is that of static initialisation,
    // which differs between builds, so a listing is always sorted.
    using Order = bool (*)(const T& a, const T& b);
    static bool by_name(const T& a, const T& b) { return a.name < b.name; }

    // `kind` names an entry in messages ("line type": "unknown line type 'x' ...").
    explicit Registry(std::string kind, Order order = by_name) : kind_(std::move(kind)), order_(order) {}

    // Adds `entry` and returns it; throws std::logic_error when its name is taken (a programming
    // error, found at start-up).
    const T& add(T entry) {
        if (const T* taken = find(entry.name))
            throw std::logic_error(kind_ + " '" + entry.name + "' registered twice (as '" + taken->name + "')");
        entries_.push_back(std::move(entry));
        return entries_.back();
    }

    // The entry of that name, the exact spelling first, then ignoring case (names are lower case;
    // what users type may not be); null when there is none.
    const T* find(std::string_view name) const {
        for (const T& e : entries_)
            if (e.name == name) return &e;
        for (const T& e : entries_)
            if (equal_ignoring_case(e.name, name)) return &e;
        return nullptr;
    }

    // As find; throws InputError("unknown KIND 'name' (choose a, b, c) (did you mean 'b'?)"),
    // the names in listing order, when there is none.
    const T& at(const std::string& name) const {
        if (const T* e = find(name)) return *e;
        std::string names;
        std::vector<std::string> candidates;
        for (const T* e : list()) {
            names += (names.empty() ? "" : ", ") + e->name;
            candidates.push_back(e->name);
        }
        throw InputError("unknown " + kind_ + " '" + name + "' (choose " + (names.empty() ? "none registered" : names) +
                         ")" + did_you_mean(name, candidates));
    }

    // Every entry in the registry's order.
    std::vector<const T*> list() const {
        std::vector<const T*> out;
        for (const T& e : entries_) out.push_back(&e);
        std::sort(out.begin(), out.end(), [this](const T* a, const T* b) { return order_(*a, *b); });
        return out;
    }

private:
    std::string kind_;
    Order order_;
    std::deque<T> entries_;  // a deque: entries never move, so what find, at and list return stays valid
};

}  // namespace inkshade
