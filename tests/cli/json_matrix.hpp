// A 4x4 matrix as the camera file and the batch metadata write it: 4 rows (glm stores columns).
#pragma once
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace inkshade::test {

inline glm::dmat4 matrix(const nlohmann::json& rows) {
    glm::dmat4 m(1.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c].get<double>();
    return m;
}

}  // namespace inkshade::test
