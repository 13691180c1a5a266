// OFF (Geomview): optional "[ST][C][N]OFF" keyword, "nv nf ne", vertices, then polygons as
// "n i0 ... i(n-1) [colour]" (fan-triangulated, face colours ignored); '#' comments anywhere.
#include <string>
#include <vector>

#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"
#include "io/readers.hpp"
#include "io/text_scanner.hpp"

namespace inkshade::io {

Mesh read_off(const std::string& path) {
    FileBytes file(path);
    TextScanner in(file.view(), path, 1, '#');

    bool has_uv = false, has_color = false, has_normal = false;
    std::string_view tok = in.token();
    if (tok.ends_with("OFF")) {
        std::string_view prefix = tok.substr(0, tok.size() - 3);
        if (prefix.starts_with("ST")) has_uv = true, prefix.remove_prefix(2);
        if (prefix.starts_with("C")) has_color = true, prefix.remove_prefix(1);
        if (prefix.starts_with("N")) has_normal = true, prefix.remove_prefix(1);
        if (!prefix.empty()) in.fail("unsupported OFF variant " + quote_token(tok));
        tok = in.token();  // counts may follow on the keyword's line
        if (tok == "BINARY") in.fail("binary OFF is not supported");
    }
    uint64_t nv = 0, nf = 0;
    if (tok.empty()) in.fail("unexpected end of file before the vertex count");
    if (!parse_number(tok, nv))
        in.fail("not an OFF file (expected 'OFF' or a vertex count but found " + quote_token(tok) + ")");
    nf = in.number_on_line<uint64_t>("a face count");
    if (!in.at_line_end()) in.number<uint64_t>("an edge count");  // unused, often absent
    // Each number needs at least two bytes (digit and separator): bounds the counts before
    // anything is allocated.
    size_t room = in.remaining() / 2 + 1;
    if (nv > room / (has_normal ? 6 : 3) || nv > UINT32_MAX)
        in.fail("header claims " + std::to_string(nv) + " vertices but file has only " +
                std::to_string(in.remaining()) + " bytes");
    if (nf > room)
        in.fail("header claims " + std::to_string(nf) + " faces but file has only " + std::to_string(in.remaining()) +
                " bytes");

    Mesh mesh;
    mesh.positions.resize(nv);
    if (has_normal) mesh.normals.resize(nv);
    if (has_color) mesh.colors.resize(nv);
    if (has_uv) mesh.uvs.resize(nv);
    for (size_t i = 0; i < nv; ++i) {
        glm::vec3& p = mesh.positions[i];
        for (int k = 0; k < 3; ++k) p[k] = in.number<float>("a vertex coordinate");
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            in.fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
        if (has_normal)
            for (int k = 0; k < 3; ++k) mesh.normals[i][k] = in.number<float>("a vertex normal");
        if (!has_color && !has_uv) continue;
        // Colour (3 or 4 values) then texture coordinates, which
        // are the line's last two values: the rest of the line decides which is which.
        float extra[8];
        int n = 0;
        for (std::string_view t = in.token_on_line(); !t.empty() && n < 8; t = in.token_on_line(), ++n)
            if (!parse_number(t, extra[n]))
                in.fail("expected a vertex colour or texture coordinate but found " + quote_token(t));
        if (has_uv) {
            if (n < 2) in.fail("vertex " + std::to_string(i) + " lacks texture coordinates");
            mesh.uvs[i] = {extra[n - 2], extra[n - 1]};
        }
        if (has_color) {
            if (n - (has_uv ? 2 : 0) < 3) in.fail("vertex " + std::to_string(i) + " lacks a colour");
            // Files write 0..1 floats or 0..255 integers; a component above 1 means the latter.
            glm::vec3 c(extra[0], extra[1], extra[2]);
            mesh.colors[i] = (c.x > 1 || c.y > 1 || c.z > 1) ? c / 255.0f : c;
        }
        if (!in.at_line_end()) in.skip_line();
    }

    mesh.triangles.reserve(nf);
    std::vector<uint32_t> polygon;
    for (uint64_t f = 0; f < nf; ++f) {
        int64_t n = in.number<int64_t>("a face vertex count");
        // Loose bound (one byte per index) so a truncated face still gets the plain
        // end-of-file message, while an absurd count cannot drive an allocation.
        if (n < 0 || uint64_t(n) > in.remaining())
            in.fail("face " + std::to_string(f) + " claims " + std::to_string(n) + " vertices but the file ends first");
        polygon.clear();
        for (int64_t j = 0; j < n; ++j) {
            int64_t idx = in.number<int64_t>("a vertex index");
            if (idx < 0 || uint64_t(idx) >= nv)
                in.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(idx) +
                        " but there are only " + std::to_string(nv) + " vertices");
            polygon.push_back(uint32_t(idx));
        }
        for (size_t j = 1; j + 1 < polygon.size(); ++j)
            mesh.triangles.emplace_back(polygon[0], polygon[j], polygon[j + 1]);
        if (!in.at_line_end()) in.skip_line();  // optional face colour
    }
    return mesh;
}

}  // namespace inkshade::io
