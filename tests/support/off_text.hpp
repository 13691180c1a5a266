// A mesh as OFF text, for tests that load what they built through the file path (welding,
// auto-smooth) as a user's file would go.
#pragma once
#include <sstream>
#include <string>

#include "inkshade/mesh.hpp"

namespace inkshade::test {

inline std::string off_text(const Mesh& m) {
    std::ostringstream out;
    out.precision(9);
    out << "OFF\n" << m.positions.size() << " " << m.triangles.size() << " 0\n";
    for (const glm::vec3& p : m.positions) out << p.x << " " << p.y << " " << p.z << "\n";
    for (const glm::uvec3& t : m.triangles) out << "3 " << t.x << " " << t.y << " " << t.z << "\n";
    return out.str();
}

}  // namespace inkshade::test
