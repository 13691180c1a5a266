// WebDataset tar shards of a batch (batch/webdataset_shards.hpp): resume keeps the shards that
// hold current jobs only; the open shard is a temporary until it is closed, so a killed run
// leaves complete shards and at most one temporary.
#include "batch/webdataset_shards.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <vector>

#include "batch/job_outputs.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "io/tar_reader.hpp"

namespace inkshade::batch {

namespace fs = std::filesystem;

namespace {

std::string regex_escape(const std::string& text) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(text, special, R"(\$&)");
}

// Each sample of a shard (key -> its metadata's job hash, "" when it has none) in order, and
// where its last member ends. Throws RuntimeError for a shard that cannot be read.
struct ShardScan {
    std::vector<std::pair<std::string, std::string>> samples;
    uint64_t end = 0;
};

ShardScan scan_shard(const std::string& path) {
    ShardScan scan;
    io::TarReader reader(path);
    while (const auto m = reader.next()) {
        const std::string key = member_key(m->name);
        if (scan.samples.empty() || scan.samples.back().first != key) scan.samples.push_back({key, ""});
        if (m->name == key + ".json") scan.samples.back().second = metadata_job_hash(reader.read(*m));
        scan.end = m->end;
    }
    return scan;
}

}  // namespace

std::string member_key(const std::string& name) {
    const size_t slash = name.rfind('/');
    const size_t dot = name.find('.', slash == std::string::npos ? 0 : slash + 1);
    return name.substr(0, dot);
}

WebDatasetShards::WebDatasetShards(std::string dir, std::string prefix, uint64_t shard_size)
    : dir_(std::move(dir)),
      prefix_(std::move(prefix)),
      staging_((fs::path(dir_) / ("." + prefix_ + ".staging")).string()),
      size_(shard_size) {}

WebDatasetShards::~WebDatasetShards() {
    if (!writer_) return;
    const std::string temp = writer_->path();
    writer_.reset();
    ::unlink(temp.c_str());
}

std::string WebDatasetShards::shard_path(size_t index) const {
    return (fs::path(dir_) / webdataset_shard_name(prefix_, index)).string();
}

std::set<std::string> WebDatasetShards::resume(const std::map<std::string, std::string>& current, bool force) {
    const std::regex shard(regex_escape(prefix_) + R"(-(\d{6})\.tar)");
    const std::regex temporary("\\." + regex_escape(prefix_) + R"(-\d{6}\.tar\.tmp-.*)");
    std::vector<size_t> indices;
    std::vector<fs::path> temporaries;  // a killed run's open shard
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir_, ec)) {
        const std::string name = entry.path().filename().string();
        std::smatch m;
        if (std::regex_match(name, m, shard)) indices.push_back(std::stoul(m[1]));
        if (std::regex_match(name, temporary)) temporaries.push_back(entry.path());
    }
    for (const fs::path& t : temporaries) fs::remove(t, ec);
    std::sort(indices.begin(), indices.end());
    std::set<std::string> kept;
    size_t n = 0;
    for (; !force && n < indices.size() && indices[n] == n; ++n) {
        ShardScan scan;
        try {
            scan = scan_shard(shard_path(n));
        } catch (const RuntimeError&) {
            break;  // unreadable: rendered again with the rest
        }
        const bool current_only =
            !scan.samples.empty() && std::all_of(scan.samples.begin(), scan.samples.end(), [&](const auto& s) {
                const auto it = current.find(s.first);
                return it != current.end() && it->second == s.second && !kept.count(s.first);
            });
        if (!current_only) break;
        for (const auto& s : scan.samples) kept.insert(s.first);
        base_end_ = scan.end;
    }
    for (size_t i = n; i < indices.size(); ++i) fs::remove(shard_path(indices[i]), ec);
    next_ = n;
    reopen_ = n > 0;
    fs::remove_all(staging_, ec);
    fs::create_directories(staging_, ec);
    if (!fs::is_directory(staging_)) throw RuntimeError(staging_ + ": cannot create the staging folder");
    return kept;
}

void WebDatasetShards::open(size_t index, uint64_t copy_bytes) {
    const std::string final_path = shard_path(index);
    std::string temp = (fs::path(dir_) / ("." + webdataset_shard_name(prefix_, index) + ".tmp-XXXXXX")).string();
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) throw RuntimeError(final_path + ": cannot create file (" + std::strerror(errno) + ")");
    ::fchmod(fd, 0644);  // mkstemp's 0600 would keep the dataset from its readers
    ::close(fd);
    writer_ = std::make_unique<io::TarWriter>(temp);
    index_ = index;
    samples_ = 0;
    if (copy_bytes == 0) return;
    // The kept shard's members, then the new samples after them: the shard grows as it would
    // have without the interruption.
    std::ifstream in(final_path, std::ios::binary);
    std::string chunk(1 << 20, '\0');
    for (uint64_t left = copy_bytes; left > 0;) {
        const size_t n = size_t(std::min<uint64_t>(left, chunk.size()));
        if (!in.read(chunk.data(), std::streamsize(n))) throw RuntimeError(final_path + ": cannot read file");
        writer_->append(std::string_view(chunk.data(), n));
        left -= n;
    }
    samples_ = 1;  // at least one, so it may be closed before the next sample
}

void WebDatasetShards::add(const std::string& sample) {
    const uint64_t end = io::tar_end().size();
    if (!writer_ && reopen_) {
        reopen_ = false;
        if (base_end_ + sample.size() + end <= size_) open(next_ - 1, base_end_);
    }
    if (writer_ && samples_ > 0 && writer_->bytes() + sample.size() + end > size_) close();
    if (!writer_) open(next_++, 0);
    writer_->append(sample);
    ++samples_;
}

void WebDatasetShards::close() {
    reopen_ = false;
    if (!writer_) return;
    writer_->finish();
    const std::string temp = writer_->path();
    writer_.reset();
    const std::string final_path = shard_path(index_);
    if (std::rename(temp.c_str(), final_path.c_str()) != 0) {
        const int err = errno;
        ::unlink(temp.c_str());
        throw RuntimeError(final_path + ": cannot write file (" + std::strerror(err) + ")");
    }
}

}  // namespace inkshade::batch
