// Checkpoint: round trip, typed access errors, unreadable files, atomic replacement.
#include "io/Checkpoint.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// A fresh directory per test, removed afterwards.
class CheckpointTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("qs_checkpoint_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        path_ = (dir_ / "checkpoint.h5").string();
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
    std::string path_;
};

/// The message of the qs::Error that `action` throws ("" if it throws none).
template <class Action>
std::string errorOf(Action action) {
    try {
        action();
    } catch (const qs::Error& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

qs::CheckpointData sample() {
    qs::CheckpointData data;
    data.putScalar("time", 12.5);
    data.putScalar("dt", 1e-5 / 3.0);
    data.put("solid/positions", std::vector<double>{0.1, 0.2, -0.3, std::numeric_limits<double>::max()});
    data.put("solid/state", std::vector<std::int64_t>{0, 1, -2, std::numeric_limits<std::int64_t>::max()});
    data.put("liquid/positions", std::vector<double>{});
    data.put("step", std::vector<std::int64_t>{123456789012345});
    return data;
}

}  // namespace

TEST_F(CheckpointTest, RoundTripKeepsEveryEntryExactly) {
    const qs::CheckpointData written = sample();
    qs::writeCheckpoint(path_, written);
    const qs::CheckpointData read = qs::readCheckpoint(path_);
    EXPECT_EQ(read.names(), written.names());
    EXPECT_EQ(read.scalar("time"), 12.5);
    EXPECT_EQ(read.scalar("dt"), 1e-5 / 3.0);  // bit-exact: a resume must continue the same run
    EXPECT_EQ(read.doubles("solid/positions"), written.doubles("solid/positions"));
    EXPECT_EQ(read.integers("solid/state"), written.integers("solid/state"));
    EXPECT_TRUE(read.doubles("liquid/positions").empty());
    EXPECT_EQ(read.integers("step"), std::vector<std::int64_t>{123456789012345});
    EXPECT_TRUE(read.has("solid/state"));
    EXPECT_FALSE(read.has("solid"));  // a group, not an entry
}

TEST_F(CheckpointTest, MissingOrMistypedEntryThrowsNamingIt) {
    const qs::CheckpointData data = sample();
    EXPECT_TRUE(contains(errorOf([&] { data.doubles("liquid/velocity"); }), "liquid/velocity"));
    EXPECT_TRUE(contains(errorOf([&] { data.integers("nothing"); }), "nothing"));
    EXPECT_TRUE(contains(errorOf([&] { data.scalar("absent"); }), "absent"));
    const std::string mistyped = errorOf([&] { data.doubles("solid/state"); });
    EXPECT_TRUE(contains(mistyped, "solid/state")) << mistyped;
    EXPECT_TRUE(contains(mistyped, "integers")) << mistyped;
    EXPECT_FALSE(errorOf([&] { data.scalar("solid/positions"); }).empty());
}

TEST_F(CheckpointTest, PutReplacesAnEntryAndRejectsBadNames) {
    qs::CheckpointData data;
    data.put("x", std::vector<double>{1.0});
    data.putScalar("x", 2.0);
    EXPECT_EQ(data.scalar("x"), 2.0);
    EXPECT_THROW(data.putScalar("", 1.0), qs::Error);
    EXPECT_THROW(data.putScalar("/x", 1.0), qs::Error);
    EXPECT_THROW(data.putScalar("a//b", 1.0), qs::Error);
    data.putScalar("x/y", 3.0);  // "x" is a dataset: it cannot also be a group
    EXPECT_TRUE(contains(errorOf([&] { qs::writeCheckpoint(path_, data); }), "clash"));
    EXPECT_FALSE(fs::exists(path_));
}

TEST_F(CheckpointTest, UnreadableFileThrowsNamingIt) {
    const std::string missing = (dir_ / "missing.h5").string();
    EXPECT_TRUE(contains(errorOf([&] { qs::readCheckpoint(missing); }), missing));

    const std::string text = (dir_ / "text.h5").string();
    std::ofstream(text) << "not hdf5\n";
    EXPECT_TRUE(contains(errorOf([&] { qs::readCheckpoint(text); }), text));

    // A valid HDF5 file that is not a checkpoint.
    const std::string foreign = (dir_ / "foreign.h5").string();
    const hid_t file = H5Fcreate(foreign.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    H5Fclose(file);
    const std::string message = errorOf([&] { qs::readCheckpoint(foreign); });
    EXPECT_TRUE(contains(message, foreign)) << message;
    EXPECT_TRUE(contains(message, "not a quicksand checkpoint")) << message;

    // A checkpoint cut in half (as a copy interrupted half way would leave it).
    qs::CheckpointData big;
    big.put("values", std::vector<double>(100000, 1.0));
    qs::writeCheckpoint(path_, big);
    fs::resize_file(path_, fs::file_size(path_) / 2);
    const std::string truncated = errorOf([&] { qs::readCheckpoint(path_); });
    EXPECT_TRUE(contains(truncated, path_));
    EXPECT_TRUE(contains(truncated, "truncated")) << truncated;
    fs::resize_file(path_, 100);
    EXPECT_TRUE(contains(errorOf([&] { qs::readCheckpoint(path_); }), "shorter than its 512-byte seal"));
}

/// Reads a whole file as bytes.
std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

TEST_F(CheckpointTest, AChangedByteAnywhereIsRefusedBeforeHdf5ReadsTheFile) {
    // HDF5 crashes on some damaged files (tests/fuzz/regressions/fuzz_checkpoint): the seal must
    // refuse every damaged checkpoint before HDF5 parses it.
    qs::CheckpointData data;
    data.put("values", std::vector<double>(300, 2.5));
    data.put("counts", std::vector<std::int64_t>{1, 2, 3});
    data.putScalar("time", 1.0);
    qs::writeCheckpoint(path_, data);
    const std::string good = readBytes(path_);
    ASSERT_GT(good.size(), 1024u);
    EXPECT_EQ(good.compare(0, 21, "quicksand-checkpoint\n"), 0);
    int refused = 0, tried = 0;
    for (std::size_t at = 0; at < good.size(); at += 37) {
        std::string bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0x5a);
        writeBytes(path_, bad);
        const std::string message = errorOf([&] { qs::readCheckpoint(path_); });
        ++tried;
        if (contains(message, "CRC-32") || contains(message, "seal") || contains(message, "not an HDF5 file")) ++refused;
        else ADD_FAILURE() << "byte " << at << ": " << (message.empty() ? "accepted" : message);
    }
    EXPECT_EQ(refused, tried);
    writeBytes(path_, good);
    EXPECT_EQ(qs::readCheckpoint(path_).doubles("values"), std::vector<double>(300, 2.5));
}

TEST_F(CheckpointTest, TheInputsThatCrashedHdf5AreRefused) {
    const std::string dir = std::string(QUICKSAND_SOURCE_DIR) + "/tests/fuzz/regressions/fuzz_checkpoint";
    int inputs = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        ++inputs;
        const std::string message = errorOf([&] { qs::readCheckpoint(entry.path().string()); });
        EXPECT_TRUE(contains(message, entry.path().string())) << message;
    }
    EXPECT_GE(inputs, 1);
}

TEST_F(CheckpointTest, WriteReplacesAtomicallyAndLeavesNoTemporary) {
    qs::CheckpointData first;
    first.putScalar("time", 1.0);
    qs::writeCheckpoint(path_, first);
    EXPECT_FALSE(fs::exists(path_ + ".tmp"));

    qs::CheckpointData second;
    second.putScalar("time", 2.0);
    qs::writeCheckpoint(path_, second);
    EXPECT_EQ(qs::readCheckpoint(path_).scalar("time"), 2.0);
    EXPECT_FALSE(fs::exists(path_ + ".tmp"));

    // A stale temporary from a crashed write is simply overwritten.
    std::ofstream(path_ + ".tmp") << "half a checkpoint";
    qs::writeCheckpoint(path_, first);
    EXPECT_EQ(qs::readCheckpoint(path_).scalar("time"), 1.0);
    EXPECT_FALSE(fs::exists(path_ + ".tmp"));

    // A write that fails leaves the previous checkpoint as it was.
    fs::remove(path_ + ".tmp");
    fs::create_directories(path_ + ".tmp/blocker");  // the temporary cannot be created
    const std::string message = errorOf([&] { qs::writeCheckpoint(path_, second); });
    EXPECT_TRUE(contains(message, path_ + ".tmp")) << message;
    EXPECT_EQ(qs::readCheckpoint(path_).scalar("time"), 1.0);
}

TEST_F(CheckpointTest, WriteIntoMissingDirectoryThrowsNamingTheFile) {
    const std::string bad = (dir_ / "no" / "such" / "checkpoint.h5").string();
    EXPECT_TRUE(contains(errorOf([&] { qs::writeCheckpoint(bad, sample()); }), bad));
}
