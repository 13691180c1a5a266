// Tar members written by io/tar_writer and read back by io/tar_reader: ustar fields as POSIX
// defines them, the prefix/name split, pax paths for long names, and truncation found.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "inkshade/error.hpp"
#include "io/tar_reader.hpp"
#include "io/tar_writer.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::io {
namespace {

std::string write_archive(const test::TempDir& dir, const std::vector<std::pair<std::string, std::string>>& files) {
    const std::string path = dir.file("a.tar");
    TarWriter writer(path);
    for (const auto& [name, data] : files) writer.append(tar_member(name, data));
    writer.finish();
    return path;
}

TEST(Tar, UstarHeaderFieldsFollowPosix) {
    const std::string m = tar_member("key/a.png", "hello");
    ASSERT_EQ(m.size(), 1024u);  // header + one padded data block
    EXPECT_EQ(std::string(m.data(), 9), "key/a.png");
    EXPECT_EQ(std::string(m.data() + 124, 12), std::string("00000000005") + '\0');  // size, octal
    EXPECT_EQ(m[156], '0');                                                         // regular file
    EXPECT_EQ(std::string(m.data() + 257, 8), std::string("ustar\0"
                                                          "00",
                                                          8));
    // The checksum: the unsigned sum of the header's bytes, its own field counted as spaces.
    unsigned sum = 0;
    for (size_t i = 0; i < 512; ++i) sum += (i >= 148 && i < 156) ? ' ' : static_cast<unsigned char>(m[i]);
    EXPECT_EQ(std::strtoul(m.data() + 148, nullptr, 8), sum);
    EXPECT_EQ(m.substr(512, 5), "hello");
    EXPECT_EQ(tar_end(), std::string(1024, '\0'));
}

TEST(Tar, LongNamesRoundTripThroughPrefixAndPax) {
    test::TempDir dir;
    const std::string split = std::string(120, 'p') + "/" + std::string(90, 'n') + ".json";  // ustar prefix
    const std::string pax = std::string(150, 'q') + "/" + std::string(150, 'r') + ".exr";    // too long for it
    const std::string data(700, 'x');
    const std::string path = write_archive(dir, {{"a.png", ""}, {split, data}, {pax, "z"}});
    TarReader reader(path);
    std::vector<std::pair<std::string, std::string>> back;
    while (const auto m = reader.next()) back.push_back({m->name, reader.read(*m)});
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back[0], std::make_pair(std::string("a.png"), std::string()));
    EXPECT_EQ(back[1], std::make_pair(split, data));
    EXPECT_EQ(back[2], std::make_pair(pax, std::string("z")));
}

TEST(Tar, TruncatedArchiveAndBadChecksumAreErrors) {
    test::TempDir dir;
    const std::string path = write_archive(dir, {{"a.png", std::string(2000, 'a')}, {"b.png", "b"}});
    std::filesystem::resize_file(path, 1500);
    TarReader cut(path);
    EXPECT_THROW(cut.next(), RuntimeError);

    std::string member = tar_member("a.png", "a");
    member[0] = 'b';  // the checksum no longer matches
    const std::string bad = dir.write("bad.tar", member + std::string(tar_end()));
    TarReader reader(bad);
    EXPECT_THROW(reader.next(), RuntimeError);
}

}  // namespace
}  // namespace inkshade::io
