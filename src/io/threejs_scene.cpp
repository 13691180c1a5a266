// Scene JSON in three.js's vocabulary (docs/threejs.md): class names for materials, lights and
// cameras, three.js's field names and defaults, its colour conventions (hex numbers and "#rrggbb"
// strings are sRGB, [r, g, b] arrays linear, as Color.setHex and Color.fromArray read them).
// Strict like style files: unknown fields are errors, so a typo never renders silently wrong.
#include "inkshade/threejs_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

using json = nlohmann::json;

constexpr size_t kMaxSceneBytes = 1 << 20;

// Parsing state: the file name for messages.
class Reader {
public:
    explicit Reader(std::string source) : source_(std::move(source)) {}

    // Field names and values come from the file and may hold line breaks ("\ntialias" is a
    // valid JSON key; found by fuzzing): control characters become '?', so the error stays one line.
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throw InputError(source_, io::one_line(field.empty() ? problem : field + ": " + problem));
    }

    void only_keys(const json& object, const std::string& field, std::initializer_list<const char*> allowed) const {
        if (!object.is_object()) fail(field, "expected an object {...}");
        for (const auto& item : object.items()) {
            const std::string& key = item.key();  // a plain reference: clang 14 cannot capture bindings
            if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) {
                std::string list;
                for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
                fail(join(field, key), "unknown field (allowed: " + list + ")");
            }
        }
    }

    static std::string join(const std::string& field, const std::string& key) {
        return field.empty() ? key : field + "." + key;
    }

    float number(const json& v, const std::string& field) const {
        if (!v.is_number()) fail(field, "expected a number");
        const double d = v.get<double>();
        if (!std::isfinite(d) || std::abs(d) > 1e30) fail(field, "expected a finite number");
        return float(d);
    }
    float number_at_least(const json& v, const std::string& field, float min) const {
        const float f = number(v, field);
        if (f < min) fail(field, "must be at least " + format_number(min) + ", got " + format_number(f));
        return f;
    }
    float positive(const json& v, const std::string& field) const {
        const float f = number(v, field);
        if (!(f > 0.0f)) fail(field, "must be greater than 0, got " + format_number(f));
        return f;
    }

    glm::vec3 vec3(const json& v, const std::string& field) const {
        if (!v.is_array() || v.size() != 3) fail(field, "expected [x, y, z]");
        return {number(v[0], field + "[0]"), number(v[1], field + "[1]"), number(v[2], field + "[2]")};
    }

    std::string string(const json& v, const std::string& field) const {
        if (!v.is_string()) fail(field, "expected a string");
        return v.get<std::string>();
    }

    bool boolean(const json& v, const std::string& field) const {
        if (!v.is_boolean()) fail(field, "expected true or false");
        return v.get<bool>();
    }

    // A three.js colour: 0xRRGGBB as a JSON number and "#rrggbb" / "#rgb" are sRGB (Color.setHex,
    // setStyle); [r, g, b] is linear (Color.fromArray). Returned with which one it was.
    struct Colour {
        glm::vec3 rgb{0.0f};
        bool srgb = true;
        glm::vec3 linear() const { return srgb ? srgb_to_linear(rgb) : rgb; }
        glm::vec3 encoded() const { return srgb ? rgb : linear_to_srgb(rgb); }
    };
    Colour colour(const json& v, const std::string& field) const {
        const std::string forms = "expected 0xRRGGBB as a number, \"#rrggbb\" (sRGB) or [r, g, b] in 0-1 (linear)";
        if (v.is_number_integer() || v.is_number_unsigned()) {
            const long long hex = v.get<long long>();
            if (hex < 0 || hex > 0xffffff) fail(field, forms);
            return {glm::vec3(float(hex >> 16 & 255), float(hex >> 8 & 255), float(hex & 255)) / 255.0f, true};
        }
        if (v.is_string()) {
            const std::string s = v.get<std::string>();
            const bool hex = s.size() > 1 && s[0] == '#' &&
                             std::all_of(s.begin() + 1, s.end(), [](unsigned char c) { return std::isxdigit(c); });
            if (!hex || (s.size() != 4 && s.size() != 7)) fail(field, forms + ", got \"" + s + "\"");
            return {glm::vec3(parse_color(s)), true};
        }
        if (v.is_array() && v.size() == 3) {
            Colour c{vec3(v, field), false};
            for (int i = 0; i < 3; ++i)
                if (c.rgb[i] < 0.0f || c.rgb[i] > 1.0f)
                    fail(field, "components must lie in 0-1 (put brightness into the intensity)");
            return c;
        }
        fail(field, forms);
    }

private:
    std::string source_;
};

struct MaterialKind {
    const char* three_name;
    const char* model;
};
constexpr MaterialKind kMaterials[] = {
    {"MeshBasicMaterial", "threejs-basic"},   {"MeshLambertMaterial", "threejs-lambert"},
    {"MeshPhongMaterial", "threejs-phong"},   {"MeshToonMaterial", "threejs-toon"},
    {"MeshNormalMaterial", "threejs-normal"}, {"MToonMaterial", "mtoon"}};

// three-vrm 3.5's MToonMaterial (VRMC_materials_mtoon by its three-vrm names), as the `mtoon`
// model in its threejs convention. `color` (three-vrm's litFactor) is the base colour; the
// factors map onto mtoon's parameters of the same meaning.
struct MtoonField {
    const char* three_name;
    const char* param;  // mtoon parameter
    bool colour;        // a THREE.Color (linear as the parameter takes it), else a number
};
constexpr MtoonField kMtoonFields[] = {{"shadeColorFactor", "shade-color", true},
                                       {"shadingShiftFactor", "shading-shift", false},
                                       {"shadingToonyFactor", "shading-toony", false},
                                       {"parametricRimColorFactor", "rim-color", true},
                                       {"parametricRimFresnelPowerFactor", "rim-fresnel-power", false},
                                       {"parametricRimLiftFactor", "rim-lift", false},
                                       {"rimLightingMixFactor", "rim-lighting-mix", false},
                                       {"outlineWidthFactor", "outline-width", false},
                                       {"outlineColorFactor", "outline-color", true},
                                       {"outlineLightingMixFactor", "outline-lighting-mix", false},
                                       {"matcapFactor", "matcap-color", true},
                                       {"shadingShiftTextureScale", "shading-shift-texture-scale", false},
                                       {"emissive", "emissive", true},
                                       {"emissiveIntensity", "emissive-intensity", false},
                                       {"uvAnimationScrollXSpeedFactor", "uv-animation-scroll-x-speed", false},
                                       {"uvAnimationScrollYSpeedFactor", "uv-animation-scroll-y-speed", false},
                                       {"uvAnimationRotationSpeedFactor", "uv-animation-rotation-speed", false}};
// MToonMaterial's outlineWidthMode strings (MToonMaterialOutlineWidthMode), in the order of
// mtoon's outline-width-mode choices.
constexpr const char* kOutlineWidthModes[] = {"none", "worldCoordinates", "screenCoordinates"};
// Fields that change nothing in a scene of this format, so they are accepted and ignored:
// giEqualizationFactor evens out light probes (an AmbientLight is already even).
constexpr const char* kMtoonIgnored[] = {"giEqualizationFactor"};
// Fields accepted only at the value that changes nothing here (three-vrm's default); any other
// value is a one-line error, as is every texture: the format cannot give one (the mesh file's
// own textures are used).
constexpr const char* kMtoonUnsupported[] = {"transparentWithZWrite",
                                             "v0CompatShade",
                                             "map",
                                             "normalMap",
                                             "emissiveMap",
                                             "shadeMultiplyTexture",
                                             "shadingShiftTexture",
                                             "matcapTexture",
                                             "rimMultiplyTexture",
                                             "outlineWidthMultiplyTexture",
                                             "uvAnimationMaskTexture"};

void read_mtoon_material(const Reader& r, const json& m, ThreejsScene& scene) {
    for (const auto& item : m.items()) {
        const std::string& key = item.key();
        const std::string field = "material." + key;
        const json& v = item.value();
        if (key == "type" || key == "name") continue;
        if (key == "color") {
            scene.base_color = r.colour(v, field).linear();
            continue;
        }
        if (key == "outlineWidthMode") {
            const std::string mode = r.string(v, field);
            const auto* it = std::find(std::begin(kOutlineWidthModes), std::end(kOutlineWidthModes), mode);
            if (it == std::end(kOutlineWidthModes))
                r.fail(field, "expected \"none\", \"worldCoordinates\" or \"screenCoordinates\", got \"" + mode + "\"");
            scene.params["outline-width-mode"] = {float(it - std::begin(kOutlineWidthModes))};
            scene.param_fields["outline-width-mode"] = field;
            continue;
        }
        const MtoonField* f = nullptr;
        for (const MtoonField& candidate : kMtoonFields)
            if (key == candidate.three_name) f = &candidate;
        if (f) {
            if (f->colour) {
                const glm::vec3 c = r.colour(v, field).linear();
                scene.params[f->param] = {c.r, c.g, c.b};
            } else {
                scene.params[f->param] = {r.number(v, field)};
            }
            scene.param_fields[f->param] = field;
            continue;
        }
        if (key == "normalScale") {
            // three.js's Vector2 as GLTFLoader sets it for a mesh without tangents: (s, -s) is
            // mtoon's normal-scale s (docs/mtoon.md, normal maps).
            if (!v.is_array() || v.size() != 2) r.fail(field, "expected [x, y] with y = -x");
            const float x = r.number(v[0], field + "[0]"), y = r.number(v[1], field + "[1]");
            if (y != -x)
                r.fail(field, "expected [x, y] with y = -x (GLTFLoader's normalScale for a mesh without tangents)");
            scene.params["normal-scale"] = {x};
            scene.param_fields["normal-scale"] = field;
            continue;
        }
        if (std::any_of(std::begin(kMtoonIgnored), std::end(kMtoonIgnored), [&](const char* k) { return key == k; })) {
            r.number(v, field);
            continue;
        }
        if (std::any_of(std::begin(kMtoonUnsupported), std::end(kMtoonUnsupported),
                        [&](const char* k) { return key == k; })) {
            // three-vrm's defaults, at which these change nothing.
            const bool harmless =
                ((key == "transparentWithZWrite" || key == "v0CompatShade") && v.is_boolean() && !v.get<bool>()) ||
                ((key.ends_with("Map") || key.ends_with("Texture")) && v.is_null());
            if (!harmless)
                r.fail(field, key.ends_with("Map") || key.ends_with("Texture")
                                  ? "a scene file cannot give a texture (the mesh file's own textures are used)"
                                  : "not supported by Inkshade's mtoon model (accepted only as three-vrm's default)");
            continue;
        }
        std::string list = "type, name, color, outlineWidthMode, normalScale";
        for (const MtoonField& k : kMtoonFields) list += ", " + std::string(k.three_name);
        for (const char* k : kMtoonIgnored) list += ", " + std::string(k);
        r.fail(field, "unknown field (allowed: " + list + ")");
    }
    // MToonMaterial on three.js r187: the threejs convention; no shadow maps unless a scene sets
    // them up (WebGLRenderer.shadowMap.enabled is false by default).
    scene.params["convention"] = {1.0f};
    scene.param_fields["convention"] = "material.type";
    scene.params["shadows"] = {0.0f};
    scene.param_fields["shadows"] = "material.type";
}

void read_material(const Reader& r, const json& m, ThreejsScene& scene) {
    if (!m.is_object()) r.fail("material", "expected an object with a \"type\"");
    if (!m.contains("type"))
        r.fail("material.type", "missing (MeshBasicMaterial, MeshLambertMaterial, ..., MToonMaterial)");
    const std::string type = r.string(m["type"], "material.type");
    const MaterialKind* kind = nullptr;
    for (const MaterialKind& k : kMaterials)
        if (type == k.three_name) kind = &k;
    if (!kind) {
        std::string list;
        for (const MaterialKind& k : kMaterials) list += (list.empty() ? "" : ", ") + std::string(k.three_name);
        r.fail("material.type", "unsupported material '" + type + "' (supported: " + list + ")");
    }
    scene.model = kind->model;
    if (type == "MToonMaterial") return read_mtoon_material(r, m, scene);
    const bool lit = type != "MeshBasicMaterial" && type != "MeshNormalMaterial";
    if (type == "MeshNormalMaterial")
        r.only_keys(m, "material", {"type", "name"});
    else if (type == "MeshBasicMaterial")
        r.only_keys(m, "material", {"type", "name", "color"});
    else if (type == "MeshPhongMaterial")
        r.only_keys(m, "material", {"type", "name", "color", "emissive", "emissiveIntensity", "specular", "shininess"});
    else if (type == "MeshToonMaterial")
        r.only_keys(m, "material", {"type", "name", "color", "emissive", "emissiveIntensity", "gradientMap"});
    else
        r.only_keys(m, "material", {"type", "name", "color", "emissive", "emissiveIntensity"});

    auto set = [&](const std::string& param, ParamValue v, const std::string& field) {
        scene.params[param] = std::move(v);
        scene.param_fields[param] = field;
    };
    // The model's colour parameters are sRGB, as three.js users type them.
    auto srgb_colour = [&](const char* key, const std::string& param) {
        if (!m.contains(key)) return;
        const glm::vec3 c = r.colour(m[key], std::string("material.") + key).encoded();
        set(param, {c.r, c.g, c.b}, std::string("material.") + key);
    };
    srgb_colour("color", "color");
    if (!lit) return;
    srgb_colour("emissive", "emissive");
    if (m.contains("emissiveIntensity"))
        set("emissive-intensity", {r.number(m["emissiveIntensity"], "material.emissiveIntensity")},
            "material.emissiveIntensity");
    srgb_colour("specular", "specular");
    if (m.contains("shininess"))
        set("shininess", {r.number(m["shininess"], "material.shininess")}, "material.shininess");
    if (m.contains("gradientMap") && !m["gradientMap"].is_null()) {
        const json& g = m["gradientMap"];
        if (!g.is_array() || g.empty())
            r.fail("material.gradientMap", "expected [v0, v1, ...]: texel values 0-1, dark end first");
        ParamValue texels;
        for (size_t i = 0; i < g.size(); ++i)
            texels.push_back(r.number(g[i], "material.gradientMap[" + std::to_string(i) + "]"));
        set("use-gradient-map", {1.0f}, "material.gradientMap");
        set("gradient-map", texels, "material.gradientMap");
    }
}

void read_lights(const Reader& r, const json& lights, ThreejsScene& scene) {
    if (!lights.is_array()) r.fail("lights", "expected an array of lights");
    bool direct = false;
    std::vector<std::pair<glm::vec3, float>> ambients;  // colour, intensity
    for (size_t i = 0; i < lights.size(); ++i) {
        const std::string field = "lights[" + std::to_string(i) + "]";
        const json& l = lights[i];
        if (!l.is_object() || !l.contains("type")) r.fail(field, "expected an object with a \"type\"");
        const std::string type = r.string(l["type"], field + ".type");
        const glm::vec3 colour =
            l.contains("color") ? r.colour(l["color"], field + ".color").linear() : glm::vec3(1.0f);
        const float intensity =
            l.contains("intensity") ? r.number_at_least(l["intensity"], field + ".intensity", 0.0f) : 1.0f;
        if (type == "AmbientLight") {
            r.only_keys(l, field, {"type", "name", "color", "intensity"});
            ambients.emplace_back(colour, intensity);
            continue;
        }
        if (type != "DirectionalLight" && type != "PointLight")
            r.fail(field + ".type",
                   "unsupported light '" + type + "' (supported: AmbientLight, DirectionalLight, PointLight)");
        if (direct)
            r.fail(field,
                   "a second direct light: Inkshade renders one DirectionalLight or PointLight (plus ambient light)");
        direct = true;
        scene.light_color = colour;
        scene.params["light-intensity"] = {intensity};
        scene.param_fields["light-intensity"] = field + ".intensity";
        if (type == "DirectionalLight") {
            r.only_keys(l, field, {"type", "name", "color", "intensity", "position", "target"});
            scene.light_type = LightType::Directional;
            // three.js: a DirectionalLight starts at Object3D.DEFAULT_UP (0, 1, 0), its target at the origin.
            scene.light_position =
                l.contains("position") ? r.vec3(l["position"], field + ".position") : glm::vec3(0, 1, 0);
            scene.light_target = l.contains("target") ? r.vec3(l["target"], field + ".target") : glm::vec3(0.0f);
            if (glm::length(*scene.light_position - *scene.light_target) == 0.0f)
                r.fail(field + ".position", "equals the target: the light has no direction");
        } else {
            r.only_keys(l, field, {"type", "name", "color", "intensity", "position", "distance", "decay"});
            scene.light_type = LightType::Point;
            scene.light_position =
                l.contains("position") ? r.vec3(l["position"], field + ".position") : glm::vec3(0.0f);
            scene.light_target = glm::vec3(0.0f);
            if (l.contains("distance")) {
                scene.params["light-distance"] = {r.number_at_least(l["distance"], field + ".distance", 0.0f)};
                scene.param_fields["light-distance"] = field + ".distance";
            }
            if (l.contains("decay")) {
                scene.params["light-decay"] = {r.number_at_least(l["decay"], field + ".decay", 0.0f)};
                scene.param_fields["light-decay"] = field + ".decay";
            }
        }
    }
    if (!direct) {
        scene.params["light-intensity"] = {0.0f};
        scene.param_fields["light-intensity"] = "lights";
    }
    // One AmbientLight keeps its colour and intensity apart; several add up (as three.js sums
    // their irradiance), written as a colour in 0-1 times an intensity.
    float intensity = 1.0f;
    if (ambients.size() == 1) {
        scene.ambient = ambients[0].first;
        intensity = ambients[0].second;
    } else if (ambients.size() > 1) {
        glm::vec3 sum(0.0f);
        for (const auto& [colour, i] : ambients) sum += colour * i;
        intensity = std::max({sum.r, sum.g, sum.b});
        scene.ambient = intensity > 0.0f ? sum / intensity : glm::vec3(0.0f);
    }
    scene.params["ambient-intensity"] = {intensity};
    scene.param_fields["ambient-intensity"] = "lights";
}

ThreejsCamera read_camera(const Reader& r, const json& c) {
    if (!c.is_object() || !c.contains("type")) r.fail("camera", "expected an object with a \"type\"");
    const std::string type = r.string(c["type"], "camera.type");
    ThreejsCamera cam;
    if (type == "PerspectiveCamera") {
        r.only_keys(c, "camera", {"type", "name", "fov", "aspect", "near", "far", "zoom", "position", "target", "up"});
        if (c.contains("fov")) cam.fov_degrees = r.number(c["fov"], "camera.fov");
        if (!(cam.fov_degrees > 0.0f && cam.fov_degrees < 180.0f)) r.fail("camera.fov", "expected degrees in (0, 180)");
    } else if (type == "OrthographicCamera") {
        r.only_keys(
            c, "camera",
            {"type", "name", "left", "right", "top", "bottom", "near", "far", "zoom", "position", "target", "up"});
        cam.orthographic = true;
        // three.js's defaults: left -1, right 1, top 1, bottom -1.
        const float left = c.contains("left") ? r.number(c["left"], "camera.left") : -1.0f;
        const float right = c.contains("right") ? r.number(c["right"], "camera.right") : 1.0f;
        const float top = c.contains("top") ? r.number(c["top"], "camera.top") : 1.0f;
        const float bottom = c.contains("bottom") ? r.number(c["bottom"], "camera.bottom") : -1.0f;
        if (!(right > left)) r.fail("camera.right", "must be greater than left");
        if (!(top > bottom)) r.fail("camera.top", "must be greater than bottom");
        // The view is centred on the target; its width follows the image's aspect.
        if (std::abs(left + right) > 1e-4f * (right - left))
            r.fail("camera.left", "left = -right expected (off-centre views are not supported)");
        if (std::abs(top + bottom) > 1e-4f * (top - bottom))
            r.fail("camera.bottom", "bottom = -top expected (off-centre views are not supported)");
        cam.ortho_height = top - bottom;
        cam.near_plane = 0.1f;
        cam.far_plane = 2000.0f;
    } else {
        r.fail("camera.type", "unsupported camera '" + type + "' (supported: PerspectiveCamera, OrthographicCamera)");
    }
    if (c.contains("aspect")) r.positive(c["aspect"], "camera.aspect");  // the image size decides
    if (!c.contains("position")) r.fail("camera.position", "missing: where the camera is, [x, y, z]");
    cam.position = r.vec3(c["position"], "camera.position");
    if (c.contains("target")) cam.target = r.vec3(c["target"], "camera.target");
    if (c.contains("up")) cam.up = r.vec3(c["up"], "camera.up");
    if (glm::length(cam.up) == 0.0f) r.fail("camera.up", "must not be zero");
    if (glm::length(cam.position - cam.target) == 0.0f)
        r.fail("camera.target", "equals the position: no view direction");
    if (c.contains("near")) cam.near_plane = r.number(c["near"], "camera.near");
    if (c.contains("far")) cam.far_plane = r.number(c["far"], "camera.far");
    if (!cam.orthographic && !(cam.near_plane > 0.0f)) r.fail("camera.near", "must be greater than 0");
    if (!(cam.far_plane > cam.near_plane)) r.fail("camera.far", "must be greater than near");
    if (c.contains("zoom")) {
        const float zoom = r.positive(c["zoom"], "camera.zoom");
        // three.js: fov' = 2 atan(tan(fov / 2) / zoom); an orthographic view shrinks by zoom.
        if (cam.orthographic)
            cam.ortho_height /= zoom;
        else
            cam.fov_degrees = glm::degrees(2.0f * std::atan(std::tan(glm::radians(0.5f * cam.fov_degrees)) / zoom));
    }
    return cam;
}

}  // namespace

ThreejsScene parse_threejs_scene(std::string_view text, const std::string& source) {
    const Reader r(source);
    if (text.size() > kMaxSceneBytes) r.fail("", "scene file larger than 1 MiB");
    json root;
    try {
        root = json::parse(text);
    } catch (const json::exception& e) {  // parse_error, and out_of_range for a number beyond double (found by fuzzing)
        std::string what = e.what();
        if (size_t p = what.find("] "); p != std::string::npos)
            what = what.substr(p + 2);  // drop "[json.exception.x.N]"
        r.fail("", "not valid JSON (" + what + ")");
    }
    r.only_keys(root, "", {"mesh", "material", "lights", "camera", "background", "outline", "size", "antialias"});

    ThreejsScene scene;
    scene.source = source;
    if (!root.contains("mesh")) r.fail("mesh", "missing: a mesh file or builtin:NAME");
    scene.mesh = r.string(root["mesh"], "mesh");
    if (scene.mesh.empty()) r.fail("mesh", "empty");
    if (!root.contains("material")) r.fail("material", "missing (e.g. {\"type\": \"MeshLambertMaterial\"})");
    read_material(r, root["material"], scene);
    read_lights(r, root.contains("lights") ? root["lights"] : json::array(), scene);
    if (root.contains("camera")) scene.camera = read_camera(r, root["camera"]);

    if (root.contains("background")) {
        const json& b = root["background"];
        if (b.is_string() && b.get<std::string>() == "transparent") scene.background = glm::vec4(0.0f);
        // three.js clears with the background converted to the output colour space: sRGB.
        else
            scene.background = glm::vec4(r.colour(b, "background").encoded(), 1.0f);
    }
    if (root.contains("outline")) {
        const json& o = root["outline"];
        r.only_keys(o, "outline", {"thickness", "color", "alpha"});
        ParamValues outline;
        if (o.contains("thickness")) outline["thickness"] = {r.number(o["thickness"], "outline.thickness")};
        if (o.contains("color")) {
            const glm::vec3 c = r.colour(o["color"], "outline.color").linear();  // OutlineEffect's colour is linear
            outline["color"] = {c.r, c.g, c.b};
        }
        if (o.contains("alpha")) outline["alpha"] = {r.number(o["alpha"], "outline.alpha")};
        scene.outline = outline;
    }
    if (root.contains("size")) {
        const json& s = root["size"];
        if (!s.is_array() || s.size() != 2 || !s[0].is_number_integer() || !s[1].is_number_integer())
            r.fail("size", "expected [width, height] in pixels");
        const int w = s[0].get<int>(), h = s[1].get<int>();
        if (w < 1 || h < 1 || w > 16384 || h > 16384) r.fail("size", "each side must be 1-16384 pixels");
        scene.size = glm::ivec2(w, h);
    }
    if (root.contains("antialias")) scene.antialias = r.boolean(root["antialias"], "antialias");
    return scene;
}

ThreejsScene load_threejs_scene(const std::string& path) {
    std::string text;
    {
        io::FileBytes bytes(path);
        if (bytes.size() > kMaxSceneBytes) throw InputError(path, "scene file larger than 1 MiB");
        text.assign(bytes.view());
    }
    ThreejsScene scene = parse_threejs_scene(text, path);
    namespace fs = std::filesystem;
    if (scene.mesh.rfind("builtin:", 0) != 0 && fs::path(scene.mesh).is_relative())
        scene.mesh = (fs::path(path).parent_path() / scene.mesh).lexically_normal().string();
    return scene;
}

}  // namespace inkshade
