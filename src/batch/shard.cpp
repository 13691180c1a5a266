// The canonical order of batch jobs and its split into shards (inkshade/batch.hpp).
#include <algorithm>
#include <charconv>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

std::vector<BatchJob> batch_order(std::vector<BatchJob> jobs) {
    // Stable: the manifest's order survives within a model, so every process that reads the
    // same manifest gets the same list (shards must agree on it).
    std::stable_sort(jobs.begin(), jobs.end(), [](const BatchJob& a, const BatchJob& b) { return a.model < b.model; });
    return jobs;
}

std::vector<BatchJob> shard(const std::vector<BatchJob>& jobs, int k, int n) {
    if (n < 1) throw InputError("shard: N must be at least 1, got " + std::to_string(n));
    if (k < 1 || k > n) throw InputError("shard: K must be in 1.." + std::to_string(n) + ", got " + std::to_string(k));
    std::vector<BatchJob> ordered = batch_order(jobs);
    const size_t count = ordered.size();
    // count * k < 2^64 for any job list that fits in memory.
    const size_t begin = size_t((unsigned long long)count * unsigned(k - 1) / unsigned(n));
    const size_t end = size_t((unsigned long long)count * unsigned(k) / unsigned(n));
    return {std::make_move_iterator(ordered.begin() + std::ptrdiff_t(begin)),
            std::make_move_iterator(ordered.begin() + std::ptrdiff_t(end))};
}

void parse_shard(const std::string& text, int& k, int& n) {
    const size_t slash = text.find('/');
    auto whole = [](std::string_view s, int& out) {
        auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
    };
    int a = 0, b = 0;
    if (slash == std::string::npos || !whole(std::string_view(text).substr(0, slash), a) ||
        !whole(std::string_view(text).substr(slash + 1), b))
        throw InputError("--shard: expected K/N (shard K of N, counted from 1), got " + io::quote_token(text));
    if (b < 1) throw InputError("--shard: N must be at least 1 in " + io::quote_token(text));
    if (a < 1 || a > b)
        throw InputError("--shard: K must be in 1.." + std::to_string(b) + " in " + io::quote_token(text) +
                         " (shards count from 1, as SLURM_ARRAY_TASK_ID=1..N)");
    k = a;
    n = b;
}

}  // namespace inkshade
