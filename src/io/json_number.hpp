// JSON numbers for the files scripts read back (camera files, transforms.json): the shortest
// decimal text that reads back to the same double, so 0.1 is written 0.1.
#pragma once
#include <charconv>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

namespace inkshade::io {

inline nlohmann::ordered_json shortest_number(double v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    if (ec != std::errc() || !std::isfinite(v)) return v;
    return std::stod(std::string(buf, end));
}

}  // namespace inkshade::io
