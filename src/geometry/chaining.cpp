// Chaining: nodes are edge keys (one set per isoline), segments are graph edges. A flat hash
// table numbers the nodes, a counting pass builds compressed adjacency (CSR) in segment order,
// then each segment is walked once — O(n) overall, and the order depends only on the input
// order.
#include "geometry/chaining.hpp"

#include <algorithm>
#include <array>

#include "geometry/key_numbering.hpp"

namespace inkshade::geometry {

std::vector<Chain> chain_order(const std::vector<LineSegment>& segments) {
    const size_t n = segments.size();
    KeyNumbering node_of(n + 1);  // a chain of n segments has about n nodes
    std::vector<std::array<uint32_t, 2>> seg_node(n);
    std::vector<char> used(n, 0);
    std::vector<uint32_t> degree;
    auto node = [&](uint64_t key, uint32_t isoline) {
        const uint32_t v = node_of.insert(key, isoline);
        if (v == degree.size()) degree.push_back(0);
        return v;
    };
    for (size_t s = 0; s < n; ++s) {
        if (segments[s].edge_a == segments[s].edge_b) {
            used[s] = 1;  // no direction: dropped
            continue;
        }
        seg_node[s] = {node(segments[s].edge_a, segments[s].isoline), node(segments[s].edge_b, segments[s].isoline)};
        ++degree[seg_node[s][0]];
        ++degree[seg_node[s][1]];
    }

    // Incidences (segment, end) per node, in segment order.
    std::vector<size_t> first(degree.size() + 1, 0);
    for (size_t v = 0; v < degree.size(); ++v) first[v + 1] = first[v] + degree[v];
    std::vector<std::pair<uint32_t, uint8_t>> incidence(first.back());
    std::vector<size_t> fill(first.begin(), first.end() - 1);
    for (size_t s = 0; s < n; ++s) {
        if (used[s]) continue;
        for (uint8_t e = 0; e < 2; ++e) incidence[fill[seg_node[s][e]]++] = {uint32_t(s), e};
    }

    // Walks from segment s's end e through nodes of degree two until a chain end or a used
    // segment (back at the start of a loop). Leaving s by its end `other`, s is walked
    // a → b when it was entered at a (e = 0).
    auto walk = [&](uint32_t s, uint8_t e) {
        Chain chain;
        const uint32_t start = seg_node[s][e];
        for (;;) {
            used[s] = 1;
            chain.segments.push_back(s);
            chain.reversed.push_back(e == 1);
            const uint8_t other = uint8_t(1 - e);
            const uint32_t v = seg_node[s][other];
            if (degree[v] != 2) break;
            auto next = incidence[first[v]];
            if (next.first == s && next.second == other) next = incidence[first[v] + 1];
            if (used[next.first]) {
                chain.closed = v == start;
                break;
            }
            s = next.first;
            e = next.second;
        }
        return chain;
    };

    std::vector<Chain> out;
    for (uint32_t s = 0; s < n; ++s)
        for (uint8_t e = 0; e < 2; ++e)
            if (!used[s] && degree[seg_node[s][e]] != 2) {
                Chain chain = walk(s, e);
                if (e == 1) {
                    // Walked from s's b end: turned round, so the chain runs along s's a → b.
                    std::reverse(chain.segments.begin(), chain.segments.end());
                    std::reverse(chain.reversed.begin(), chain.reversed.end());
                    for (auto& r : chain.reversed) r = !r;
                }
                const uint32_t head = seg_node[chain.segments.front()][chain.reversed.front() ? 1 : 0];
                const uint32_t tail = seg_node[chain.segments.back()][chain.reversed.back() ? 0 : 1];
                chain.component = degree[head] == 1 && degree[tail] == 1;
                out.push_back(std::move(chain));
            }
    for (uint32_t s = 0; s < n; ++s)
        if (!used[s]) {
            out.push_back(walk(s, 0));
            out.back().component = out.back().closed;
        }
    return out;
}

std::vector<Polyline> chain_segments(const std::vector<LineSegment>& segments, bool faces) {
    const std::vector<Chain> chains = chain_order(segments);
    std::vector<Polyline> out;
    out.reserve(chains.size());
    for (const Chain& chain : chains) {
        Polyline line;
        line.closed = chain.closed;
        const size_t k = chain.segments.size();
        line.points.reserve(k + 1);
        line.strength.reserve(k + 1);
        for (size_t i = 0; i < k; ++i) {
            const LineSegment& s = segments[chain.segments[i]];
            const bool r = chain.reversed[i];
            if (i == 0) {
                line.points.push_back(r ? s.b : s.a);
                line.strength.push_back(r ? s.strength_b : s.strength_a);
            }
            if (i + 1 < k || !chain.closed) {  // a loop does not repeat its start point
                line.points.push_back(r ? s.a : s.b);
                line.strength.push_back(r ? s.strength_a : s.strength_b);
            }
            if (faces) line.faces.push_back(s.face);  // the face from point i to point i + 1
        }
        if (faces && !chain.closed) line.faces.push_back(line.faces.back());  // the last point's
        out.push_back(std::move(line));
    }
    return out;
}

float polyline_length(const Polyline& line) {
    const auto& p = line.points;
    double length = 0.0;
    for (size_t i = 1; i < p.size(); ++i) length += glm::distance(glm::dvec3(p[i - 1]), glm::dvec3(p[i]));
    if (line.closed && p.size() > 2) length += glm::distance(glm::dvec3(p.back()), glm::dvec3(p.front()));
    return float(length);
}

std::vector<Polyline> drop_short(std::vector<Polyline> polylines, float min_length) {
    std::erase_if(polylines, [&](const Polyline& l) { return !(polyline_length(l) >= min_length); });
    return polylines;
}

void smooth_polylines(std::vector<Polyline>& polylines, int iterations, float weight) {
    std::vector<glm::vec3> next;
    for (Polyline& line : polylines) {
        auto& p = line.points;
        const size_t n = p.size();
        if (n < 3) continue;  // nothing between fixed ends (or too short a loop to smooth)
        for (int it = 0; it < iterations; ++it) {
            next = p;  // Jacobi update: every point moves from the same old neighbours
            const size_t first = line.closed ? 0 : 1, last = line.closed ? n : n - 1;
            for (size_t i = first; i < last; ++i) {
                const glm::vec3& prev = p[(i + n - 1) % n];
                const glm::vec3& succ = p[(i + 1) % n];
                next[i] = p[i] + weight * (0.5f * (prev + succ) - p[i]);
            }
            p.swap(next);
        }
    }
}

}  // namespace inkshade::geometry
