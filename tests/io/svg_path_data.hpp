// Reads the path data the SVG writer emits (absolute M, L, C, Z with implicit repeats, as in
// "M1 2 L3 4 5 6 C..."): the subpaths' pieces as cubic Béziers (a line is a cubic with its
// control points on it), to sample what an SVG viewer draws.
#pragma once
#include <cctype>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/bezier_fit.hpp"

namespace inkshade::test {

struct SvgSubpath {
    std::vector<io::CubicBezier> pieces;
    bool closed = false;
};

inline std::vector<SvgSubpath> parse_path_data(const std::string& d) {
    std::vector<SvgSubpath> out;
    size_t i = 0;
    char command = 0;
    glm::dvec2 current(0.0), start(0.0);
    auto skip = [&] {
        while (i < d.size() && (std::isspace(static_cast<unsigned char>(d[i])) || d[i] == ',')) ++i;
    };
    auto number = [&]() {
        skip();
        const char* begin = d.c_str() + i;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (end == begin) ADD_FAILURE() << "a number expected at " << i << " in " << d.substr(0, 200);
        i += size_t(end - begin);
        return v;
    };
    auto point = [&]() {
        const double x = number();
        return glm::dvec2(x, number());
    };
    while (true) {
        skip();
        if (i >= d.size()) break;
        if (std::isalpha(static_cast<unsigned char>(d[i]))) command = d[i++];
        switch (command) {
            case 'M':
                current = start = point();
                out.push_back({});
                command = 'L';  // pairs after M are lines
                break;
            case 'L': {
                const glm::dvec2 q = point();
                out.back().pieces.push_back({current, current + (q - current) / 3.0, q - (q - current) / 3.0, q});
                current = q;
                break;
            }
            case 'C': {
                const glm::dvec2 c1 = point(), c2 = point(), e = point();
                out.back().pieces.push_back({current, c1, c2, e});
                current = e;
                break;
            }
            case 'Z':
                if (current != start)
                    out.back().pieces.push_back(
                        {current, current + (start - current) / 3.0, start - (start - current) / 3.0, start});
                out.back().closed = true;
                current = start;
                command = 0;
                break;
            default: ADD_FAILURE() << "unexpected command '" << command << "' in " << d.substr(0, 200); return out;
        }
    }
    return out;
}

// Points along every piece, `per_piece` + 1 a piece.
inline std::vector<glm::dvec2> sample_path_data(const std::string& d, int per_piece = 32) {
    std::vector<glm::dvec2> out;
    for (const SvgSubpath& s : parse_path_data(d))
        for (const io::CubicBezier& b : s.pieces)
            for (int k = 0; k <= per_piece; ++k) out.push_back(b.at(double(k) / per_piece));
    return out;
}

}  // namespace inkshade::test
