// Whether an output file's bytes read as their kind (--verify): enough of each format to
// catch a file that is missing its end or is not that kind at all, without decoding it.
#pragma once
#include <string>
#include <string_view>

namespace inkshade::batch {

// "" when `bytes` read as the kind its name's extension says (.png: signature, chunks up to
// IEND; .json: parses; .exr: magic, header and every scan-line chunk inside the file; .svg:
// an <svg> element closed at the end; others: present), else what is wrong.
std::string output_problem(const std::string& name, std::string_view bytes);

}  // namespace inkshade::batch
