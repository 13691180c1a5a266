// The tar shards of one prefix in a batch's output directory (the WebDataset layout,
// docs/cli.md#batch): the existing ones read back on resume, the open one written as a hidden
// temporary and renamed when it is closed, and the staging folder the jobs are written into
// before they are packed.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "io/tar_writer.hpp"

namespace inkshade::batch {

class WebDatasetShards {
public:
    WebDatasetShards(std::string dir, std::string prefix, uint64_t shard_size);
    ~WebDatasetShards();  // removes the open shard's temporary when it was not closed
    WebDatasetShards(const WebDatasetShards&) = delete;
    WebDatasetShards& operator=(const WebDatasetShards&) = delete;

    // Keeps the longest run of shards PREFIX-000000.tar, PREFIX-000001.tar, ... whose every
    // sample is a key of `current` holding that job hash in its metadata (KEY.json), once
    // (none with `force`); removes the prefix's other shards, the temporaries a killed run
    // left, and the staging folder, which it makes anew. Returns the kept samples' keys.
    std::set<std::string> resume(const std::map<std::string, std::string>& current, bool force);

    // Appends one sample (tar members, io::tar_member's bytes). The open shard is closed first
    // when the sample would take it past the shard size (a shard holds at least one sample);
    // the last kept shard is reopened when the first sample still fits in it.
    void add(const std::string& sample);
    // Closes the open shard: end blocks, fsync, rename to its name. Nothing when none is open.
    void close();

    // Where the jobs are written before they are packed: DIR/.PREFIX.staging.
    const std::string& staging() const { return staging_; }

private:
    void open(size_t index, uint64_t copy_bytes);
    std::string shard_path(size_t index) const;

    std::string dir_, prefix_, staging_;
    uint64_t size_;
    std::unique_ptr<io::TarWriter> writer_;  // the open shard's temporary
    size_t index_ = 0;                       // the open shard's index
    size_t next_ = 0;                        // the index of the next new shard
    size_t samples_ = 0;                     // in the open shard
    bool reopen_ = false;                    // the last kept shard may take the first sample
    uint64_t base_end_ = 0;                  // the last kept shard's bytes before its end blocks
};

// The sample of a job written into `staging`: its files as tar members KEY + extension (the
// metadata's "outputs" list them; the metadata KEY.json last), read, then removed from the
// staging folder. Throws RuntimeError for a file that is missing or not named after the stem.
std::string take_staged_sample(const std::string& staging, const std::string& stem);

// The key of a tar member's name: up to the first '.' of its last path component.
std::string member_key(const std::string& name);

}  // namespace inkshade::batch
