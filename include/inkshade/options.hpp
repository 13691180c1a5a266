// The scene options, each declared once (name, value, default, range or choices, help, which
// front ends take it, how the batch job hash and metadata record it), as ffmpeg's AVOption
// tables declare an option once for its command line, its API and its documentation. The
// command line's flags and --help (`render`, `lines`, `view`, `batch`), the batch manifest's
// columns, the Python keywords and their docstrings, the job hash, the job metadata and the
// option table of docs/cli.md all read this table; docs/architecture.md says how to add one.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/io.hpp"
#include "inkshade/scene.hpp"

namespace inkshade {

// Where an option is taken: the commands that draw one scene, `batch` (a flag and a manifest
// column, and a keyword of Python's batch()) and Python's render/lines/svg keywords.
enum OptionFront : unsigned {
    kRender = 1u << 0,
    kLines = 1u << 1,
    kView = 1u << 2,
    kBatch = 1u << 3,
    kPython = 1u << 4,
};

// What an option's value is, which decides how it is parsed and written.
enum class OptionKind {
    Number,    // a finite float in the option's range
    Integer,   // an int in the option's range (or one of its choices)
    Flag,      // true or false; a command-line flag takes no value
    Text,      // any non-empty text
    Choice,    // one of `choices`
    Vector,    // x,y,z
    Color,     // parse_color: a name, #rrggbb, r,g,b (or r,g,b,a where the option takes alpha)
    Size,      // WxH
    Names,     // names separated by ',' or ';' (the AOVs)
    Weights,   // NAME=W items (repeatable on the command line; ',' or ';' in a manifest cell)
    Levels,    // occlusion levels A-B, A or A-
    Overrides  // [model.]param=value, repeatable (--set)
};

using OptionValue = std::variant<std::monostate, float, int, bool, std::string, glm::vec3, glm::vec4, glm::ivec2,
                                 std::vector<std::string>, std::vector<NamedWeight>, OcclusionLevels>;

// Where the batch job hash writes an option (batch/job_hash.cpp): on the view's line or the
// image's, always or only when it is not the default, so that options added later leave the
// hashes of earlier jobs as they were.
enum class HashUse { None, ViewAlways, ViewWhenSet, ImageWhenSet };

struct OptionSpec {
    std::string name;   // --NAME, manifest column NAME, Python keyword NAME with '_' for '-'
    OptionKind kind;
    std::string value;  // the value's placeholder in help: DEG, x,y,z, WxH, ...
    std::string help;   // one line: --help, Python docstrings and the docs table
    unsigned fronts = 0;
    double min = 0.0, max = 0.0;  // Number and Integer: the range, when min < max
    bool min_open = false, max_open = false;
    std::string unit;                  // for range errors: "degrees", "seconds", ...
    std::vector<std::string> choices;  // Choice, and an Integer taking only these
    HashUse hash = HashUse::None;
    std::string metadata;  // batch metadata key ("view.margin" nests), empty: none
    // The value of the option in a request: std::monostate where it is unset (auto, the style's).
    std::function<OptionValue(const SceneRequest&)> get;
    // Stores a value of the option's kind, already checked (parse_option and check_option_value);
    // std::monostate puts SceneRequest's default back.
    std::function<void(SceneRequest&, const OptionValue&)> put;
    // The job hash's spelling of a value, for the options whose earlier spelling was not the
    // canonical text (ortho as 0/1); empty: format_option_hash.
    std::function<std::string(const OptionValue&)> hash_text;

    bool takes(unsigned front) const { return (fronts & front) != 0; }
    bool has_range() const { return min < max; }
};

// Every scene option, in the order --help lists them and the job hash writes them.
const std::vector<OptionSpec>& scene_options();

// The option named `name` (command-line spelling without dashes, or a Python keyword), or
// null.
const OptionSpec* find_option(std::string_view name);

// The request every front end starts from: SceneRequest's defaults, with the image size of a
// dataset (512x512) for batch and Python, whose images are many.
SceneRequest default_request(unsigned front);

// How errors name an option given by `names` (--fov, fov).
std::string option_label(const OptionSpec& spec, OptionNames names);

// The value `text` gives the option (command line, manifest cell): InputError naming it for
// text that is not one, an empty text included, and for a value out of the option's range.
OptionValue parse_option(const OptionSpec& spec, const std::string& text, OptionNames names = OptionNames::Cli);

// InputError when `value` is out of the option's range or not one of its choices; with `text`,
// the message repeats the text it was read from.
void check_option_value(const OptionSpec& spec, const OptionValue& value, OptionNames names,
                        const std::string* text = nullptr);

// Every option value of the request checked against its range and choices (make_scene does).
void check_option_values(const SceneRequest& request);

// parse_option, then stored in the request (a repeatable option appends).
void set_option(SceneRequest& request, const OptionSpec& spec, const std::string& text);
// The same, replacing what the request had (a manifest cell gives the whole list), its errors
// naming the option as `names` spells it.
void replace_option(SceneRequest& request, const OptionSpec& spec, const std::string& text, OptionNames names);

// The value as the command line would give it ("0.05", "1,2,3", "512x512", "happy=1;blink=0.5");
// empty for std::monostate.
std::string format_option(const OptionSpec& spec, const OptionValue& value);

// Whether the request sets the option to something other than SceneRequest's default: what
// the job hash and the metadata record of a ...WhenSet option, so earlier jobs keep theirs.
bool option_is_set(const OptionSpec& spec, const SceneRequest& request);

// Items separated by ',' or ';', blanks around them trimmed, empty ones left out.
std::vector<std::string> split_option_list(const std::string& text);

// The option's default in `front`'s requests, as text ("" when unset by default).
std::string option_default(const OptionSpec& spec, unsigned front);

// The job hash's text of a value: floats as %.9g (exact), the rest as format_option.
std::string format_option_hash(const OptionSpec& spec, const OptionValue& value);

// The rows of the docs/cli.md option table: one per option, with the fronts that take it.
std::string format_option_table_markdown();

}  // namespace inkshade
