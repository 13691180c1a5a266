// The names of the WebDataset layout (inkshade/batch.hpp): --layout, sample keys, shard file
// names and --shard-size.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

BatchLayout parse_layout(const std::string& text) {
    if (text == "folder") return BatchLayout::Folder;
    if (text == "webdataset") return BatchLayout::WebDataset;
    throw InputError("--layout: expected folder or webdataset, got " + io::quote_token(text));
}

std::string webdataset_key(const std::string& stem) {
    // WebDataset's tar reader (webdataset.tariterators.base_plus_ext) takes a file's key as its
    // path up to the first dot of the last component, the rest as the extension: a dot in a key
    // would move the split.
    std::string key = stem;
    for (char& c : key)
        if (c == '.') c = '_';
    return key;
}

void check_webdataset_keys(const std::vector<BatchJob>& jobs) {
    std::map<std::string, const BatchJob*> seen;
    for (const BatchJob& job : jobs) {
        const auto [it, fresh] = seen.emplace(webdataset_key(job.stem), &job);
        if (!fresh)
            throw InputError(job.source + ": WebDataset key '" + it->first + "' of '" + job.stem +
                             "' is also the key of '" + it->second->stem + "' (" + it->second->source +
                             "; keys have '_' for '.')");
    }
}

std::string webdataset_shard_prefix(const std::string& prefix, int k, int n) {
    if (prefix.empty() || prefix.front() == '.' || prefix.find('/') != std::string::npos)
        throw InputError("--shard-prefix: expected a file name without '/' that does not start with '.', got " +
                         io::quote_token(prefix));
    if (n <= 0) return prefix;
    const std::string total = std::to_string(n), index = std::to_string(k);
    return prefix + "-" + std::string(total.size() > index.size() ? total.size() - index.size() : 0, '0') + index +
           "of" + total;
}

uint64_t parse_shard_size(const std::string& text) {
    const std::string bad =
        "--shard-size: expected a positive size such as 1GB, 256MiB or 1000000 (bytes), got " + io::quote_token(text);
    double number = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, number);
    if (ec != std::errc() || text.empty() || !std::isdigit(static_cast<unsigned char>(text[0]))) throw InputError(bad);
    std::string unit(ptr, end);
    for (char& c : unit) c = char(std::tolower(static_cast<unsigned char>(c)));
    static const std::map<std::string, double> units = {
        {"", 1.0},       {"b", 1.0},      {"kb", 1e3},     {"mb", 1e6}, {"gb", 1e9}, {"tb", 1e12}, {"kib", 0x1p10},
        {"mib", 0x1p20}, {"gib", 0x1p30}, {"tib", 0x1p40}, {"k", 1e3},  {"m", 1e6},  {"g", 1e9},   {"t", 1e12}};
    const auto u = units.find(unit);
    if (u == units.end()) throw InputError(bad);
    const double bytes = std::floor(number * u->second);
    if (!(bytes >= 1.0)) throw InputError("--shard-size: must be at least 1 byte, got " + io::quote_token(text));
    if (bytes > 0x1p62) throw InputError("--shard-size: too large, got " + io::quote_token(text));
    return uint64_t(bytes);
}

std::string webdataset_shard_name(const std::string& prefix, size_t index) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%06zu", index);
    return prefix + "-" + digits + ".tar";
}

}  // namespace inkshade
