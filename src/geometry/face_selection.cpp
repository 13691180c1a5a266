#include "geometry/face_selection.hpp"

#include <algorithm>
#include <string>

#include "geometry/coincident_vertices.hpp"

namespace inkshade::geometry {

namespace {

bool any_match(const std::vector<std::string>& patterns, const std::string& name) {
    return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& p) { return glob_match(p, name); });
}

// Per name of `names` (and "" for an index past them, at the end): whether any pattern matches.
std::vector<uint8_t> matching_names(const std::vector<std::string>& patterns, const std::vector<std::string>& names) {
    std::vector<uint8_t> out(names.size() + 1);
    for (size_t i = 0; i < names.size(); ++i) out[i] = any_match(patterns, names[i]);
    out.back() = any_match(patterns, "");
    return out;
}

// Whether the per-face index list `ids` (empty: all faces index past `table`) matches at face f.
bool matches(const std::vector<uint8_t>& table, const std::vector<uint32_t>& ids, size_t f) {
    const size_t i = f < ids.size() ? std::min<size_t>(ids[f], table.size() - 1) : table.size() - 1;
    return table[i] != 0;
}

bool mark_matches(int wanted, uint8_t mark) { return wanted < 0 ? mark != 0 : mark == wanted; }

}  // namespace

std::vector<uint8_t> selected_faces(const Mesh& mesh, const FaceSelection& selection) {
    const size_t n = mesh.triangles.size();
    std::vector<std::string> material_names;
    for (const Material& m : mesh.materials) material_names.push_back(m.name);
    const std::vector<uint8_t> materials = matching_names(selection.materials, material_names);
    const std::vector<uint8_t> objects = matching_names(selection.objects, mesh.object_names);
    std::vector<uint8_t> out(n);
    for (size_t f = 0; f < n; ++f) {
        bool take = true;
        if (!selection.materials.empty()) take = take && matches(materials, mesh.face_materials, f);
        if (!selection.objects.empty()) take = take && matches(objects, mesh.face_objects, f);
        if (selection.face_mark)
            take = take && mark_matches(*selection.face_mark, f < mesh.face_marks.size() ? mesh.face_marks[f] : 0);
        out[f] = uint8_t(take != selection.invert);
    }
    return out;
}

SelectedFaces::SelectedFaces(const Mesh& mesh, const FaceSelection& selection)
    : selected_(selected_faces(mesh, selection)), canonical_(canonical_vertices(mesh)) {
    for (size_t f = 0; f < selected_.size(); ++f) {
        if (!selected_[f]) continue;
        const glm::uvec3 t = mesh.triangles[f];
        if (t.x >= canonical_.size() || t.y >= canonical_.size() || t.z >= canonical_.size()) continue;
        for (int e = 0; e < 3; ++e) edges_.insert(edge_key(canonical_[t[e]], canonical_[t[(e + 1) % 3]]));
    }
}

bool SelectedFaces::keeps(const LineSegment& s) const {
    for (uint32_t f : {s.face, s.owned ? kNoFace : s.face_b})
        if (f < selected_.size() && selected_[f]) return true;
    const auto vertex = [](uint64_t key) { return uint32_t(key >> 32) == uint32_t(key); };
    if (!vertex(s.edge_a) || !vertex(s.edge_b)) return false;
    const uint32_t a = uint32_t(s.edge_a), b = uint32_t(s.edge_b);
    if (a >= canonical_.size() || b >= canonical_.size()) return false;
    return edges_.contains(edge_key(canonical_[a], canonical_[b]));
}

void SelectedFaces::filter(std::vector<LineSegment>& segments) const {
    std::erase_if(segments, [this](const LineSegment& s) { return !keeps(s); });
}

}  // namespace inkshade::geometry
