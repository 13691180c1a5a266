// The AOV files beside an image (inkshade/aov.hpp, docs/aov.md), each written atomically.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "inkshade/aov.hpp"
#include "inkshade/error.hpp"
#include "io/atomic_file.hpp"
#include "io/exr_writer.hpp"
#include "io/png_samples.hpp"

namespace inkshade {

namespace {

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

void check_size(const std::string& path, size_t have, size_t want) {
    if (have != want) throw RuntimeError(path + ": the AOV buffer does not match the image size");
}

// Ids above 65535 do not fit the 16-bit PNG: they are clamped (the library and Python keep 32 bits).
std::vector<uint16_t> to_16_bits(const std::vector<uint32_t>& ids) {
    std::vector<uint16_t> out(ids.size());
    std::transform(ids.begin(), ids.end(), out.begin(), [](uint32_t v) { return uint16_t(std::min(v, 65535u)); });
    return out;
}

// The surface fields written as EXR, in Aov's order.
constexpr Aov kFloatFields[] = {Aov::Ndotv, Aov::Kr, Aov::Dwkr, Aov::K1, Aov::K2, Aov::Pdir1, Aov::Pdir2};

std::string shading_name(int scale) { return "shading-s" + std::to_string(scale); }

// A field's EXR: channel Y (one float a pixel) or X and Y (pdir1, pdir2).
void write_field(const std::string& path, const AovImages& a, Aov aov) {
    const std::vector<float>& v = field_buffer(a, aov);
    const size_t channels = size_t(field_channels(aov));
    check_size(path, v.size(), size_t(a.width) * size_t(a.height) * channels);
    if (channels == 1)
        io::write_exr(path, a.width, a.height, {{"Y", v.data(), 1}}, io::ExrCompression::Rle);
    else
        io::write_exr(path, a.width, a.height, {{"X", v.data(), 2}, {"Y", v.data() + 1, 2}}, io::ExrCompression::Rle);
}

// n·l in [0, 1] as 16-bit gray: round(v · 65535).
void write_shading(const std::string& path, const AovImages& a, const std::vector<float>& v) {
    check_size(path, v.size(), size_t(a.width) * size_t(a.height));
    std::vector<uint16_t> gray(v.size());
    // y + 0.5 is exact in double, so truncating it rounds as lround(y) does, without its call.
    std::transform(v.begin(), v.end(), gray.begin(), [](float x) {
        const float y = std::clamp(x, 0.0f, 1.0f) * 65535.0f;
        return uint16_t(double(y) + 0.5);
    });
    io::write_png_samples(path, a.width, a.height, 1, gray.data());
}

}  // namespace

std::vector<std::string> aov_file_names(const std::string& image_path, AovSet set,
                                        const std::vector<std::string>& line_masks,
                                        const std::vector<std::string>& linesets) {
    std::vector<std::string> out;
    auto add = [&](Aov aov, const char* ext) {
        if (set.contains(aov)) out.push_back(file_name(aov_path(image_path, aov_name(aov), ext)));
    };
    add(Aov::Depth, ".exr");
    add(Aov::Normal, ".png");
    add(Aov::Id, ".png");
    add(Aov::Material, ".png");
    add(Aov::Mask, ".png");
    if (set.contains(Aov::Lines))
        for (const std::string& name : line_masks) out.push_back(file_name(aov_path(image_path, name, ".png")));
    if (set.contains(Aov::LineSets))
        for (const std::string& name : linesets)
            out.push_back(file_name(aov_path(image_path, "lineset-" + name, ".png")));
    for (Aov aov : kFloatFields) add(aov, ".exr");
    if (set.contains(Aov::ShadingScales))
        for (int k = 0; k < kShadingScales; ++k)
            out.push_back(file_name(aov_path(image_path, shading_name(k), ".png")));
    if (!set.empty()) out.push_back(file_name(aov_path(image_path, "camera", ".json")));
    return out;
}

std::vector<std::string> write_aov_files(const std::string& image_path, AovSet set, const AovImages& a,
                                         const CameraRecord& camera) {
    // Each file is encoded and written by a task of its own (a dataset view writes a dozen:
    // their zlib and EXR encodings are independent), listed in the order of aov_file_names.
    std::vector<std::pair<std::string, std::function<void(const std::string&)>>> files;
    const int w = a.width, h = a.height;
    const size_t pixels = size_t(w) * size_t(h);
    auto path_of = [&](Aov aov, const char* ext) { return aov_path(image_path, aov_name(aov), ext); };
    if (set.contains(Aov::Depth))
        files.emplace_back(path_of(Aov::Depth, ".exr"), [&](const std::string& path) {
            check_size(path, a.depth.size(), pixels);
            io::write_exr(path, w, h, {{"Z", a.depth.data(), 1}});
        });
    if (set.contains(Aov::Normal))
        files.emplace_back(path_of(Aov::Normal, ".png"), [&](const std::string& path) {
            check_size(path, a.normal.size(), pixels * 3);
            // n * 0.5 + 0.5 in 16 bits; the background (0, 0, 0) is not a unit vector.
            std::vector<uint16_t> rgb(a.normal.size(), 0);
            for (size_t p = 0; p < pixels; ++p) {
                const float* n = &a.normal[3 * p];
                if (n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f) continue;
                for (int c = 0; c < 3; ++c)
                    rgb[3 * p + c] = uint16_t(std::lround(std::clamp(n[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 65535.0f));
            }
            io::write_png_samples(path, w, h, 3, rgb.data());
        });
    for (Aov aov : {Aov::Id, Aov::Material})
        if (set.contains(aov))
            files.emplace_back(path_of(aov, ".png"), [&, aov](const std::string& path) {
                const std::vector<uint32_t>& ids = aov == Aov::Id ? a.id : a.material;
                check_size(path, ids.size(), pixels);
                io::write_png_samples(path, w, h, 1, to_16_bits(ids).data());
            });
    auto add_gray = [&](const std::string& path, const std::vector<uint8_t>& v) {
        files.emplace_back(path, [&](const std::string& p) {
            check_size(p, v.size(), pixels);
            io::write_png_samples(p, w, h, 1, v.data());
        });
    };
    if (set.contains(Aov::Mask)) add_gray(path_of(Aov::Mask, ".png"), a.mask);
    if (set.contains(Aov::Lines))
        for (const LineMask& m : a.lines)
            add_gray(aov_path(image_path, line_mask_name(m.lineset, m.type), ".png"), m.pixels);
    if (set.contains(Aov::LineSets))
        for (const LineSetMask& m : a.linesets)
            add_gray(aov_path(image_path, "lineset-" + m.lineset, ".png"), m.pixels);
    for (Aov aov : kFloatFields)
        if (set.contains(aov))
            files.emplace_back(path_of(aov, ".exr"), [&, aov](const std::string& path) { write_field(path, a, aov); });
    if (set.contains(Aov::ShadingScales))
        for (int k = 0; k < kShadingScales; ++k)
            files.emplace_back(aov_path(image_path, shading_name(k), ".png"), [&, k](const std::string& path) {
                if (size_t(k) >= a.shading.size()) throw RuntimeError(path + ": no such shading scale was rendered");
                write_shading(path, a, a.shading[size_t(k)]);
            });
    if (!set.empty())
        files.emplace_back(path_of(Aov::Camera, ".json"), [&](const std::string& path) {
            CameraRecord record = camera;
            if (!set.fields().empty()) record.fields = a.field_scales;
            io::write_file_atomic(path, format_camera_json(record));
        });
    tbb::parallel_for(size_t(0), files.size(), [&](size_t i) { files[i].second(files[i].first); });
    std::vector<std::string> written;
    for (const auto& f : files) written.push_back(file_name(f.first));
    return written;
}

}  // namespace inkshade
