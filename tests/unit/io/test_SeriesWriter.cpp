// SeriesWriter: header and lines, precision, row size check, resume truncation.
#include "io/SeriesWriter.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// A fresh directory per test, removed afterwards.
class SeriesWriterTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("qs_series_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        path_ = (dir_ / "series.csv").string();
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string content() const {
        std::ifstream in(path_);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    fs::path dir_;
    std::string path_;
    const std::vector<std::string> columns_ = {"time", "gate_flux", "q_mid"};
};

}  // namespace

TEST_F(SeriesWriterTest, WritesHeaderAndFullPrecisionLinesFlushedOneByOne) {
    qs::SeriesWriter series(path_, columns_);
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n");
    series.write({0.0, 1.0 / 3.0, -2.5e-7});
    // Visible before the writer closes: a running simulation can be plotted.
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n0,0.333333333,-2.5e-07\n");
    series.write({0.1, 123456789.0, 1e300});
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n0,0.333333333,-2.5e-07\n0.1,123456789,1e+300\n");
}

TEST_F(SeriesWriterTest, RowOfWrongSizeThrows) {
    qs::SeriesWriter series(path_, columns_);
    EXPECT_THROW(series.write({1.0, 2.0}), qs::Error);
    EXPECT_THROW(series.write({1.0, 2.0, 3.0, 4.0}), qs::Error);
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n");
}

TEST_F(SeriesWriterTest, BadColumnNamesThrow) {
    EXPECT_THROW(qs::SeriesWriter(path_, {}), qs::Error);
    EXPECT_THROW(qs::SeriesWriter(path_, {"time", "a,b"}), qs::Error);
    EXPECT_THROW(qs::SeriesWriter(path_, {"time", ""}), qs::Error);
}

TEST_F(SeriesWriterTest, CannotOpenThrowsNamingThePath) {
    const std::string bad = (dir_ / "missing" / "series.csv").string();
    try {
        qs::SeriesWriter series(bad, columns_);
        FAIL() << "expected qs::Error";
    } catch (const qs::Error& e) {
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
    EXPECT_THROW(qs::SeriesWriter(bad, columns_, true, 0.0), qs::Error);
}

TEST_F(SeriesWriterTest, ResumeKeepsLinesUpToTheResumeTimeAndContinues) {
    {
        qs::SeriesWriter series(path_, columns_);
        for (int i = 0; i <= 5; ++i) series.write({0.1 * i, double(i), -double(i)});
    }
    {
        // 0.1 * 3 = 0.30000000000000004 was printed as 0.3: it must be kept for resumeTime 0.3.
        qs::SeriesWriter series(path_, columns_, true, 0.3);
        EXPECT_EQ(content(), "time,gate_flux,q_mid\n0,0,-0\n0.1,1,-1\n0.2,2,-2\n0.3,3,-3\n");
        series.write({0.35, 7.0, 8.0});
    }
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n0,0,-0\n0.1,1,-1\n0.2,2,-2\n0.3,3,-3\n0.35,7,8\n");
    EXPECT_FALSE(fs::exists(path_ + ".tmp"));
}

TEST_F(SeriesWriterTest, ResumeDropsHalfWrittenAndMalformedLines) {
    std::ofstream(path_) << "time,gate_flux,q_mid\n0,1,2\n0.1,1\nabc,1,2\n0.2,1,2x\n0.05,3,4\n0.1,5";
    {
        qs::SeriesWriter series(path_, columns_, true, 1.0);
        series.write({0.2, 6.0, 7.0});
    }
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n0,1,2\n0.05,3,4\n0.2,6,7\n");
}

TEST_F(SeriesWriterTest, ResumeRefusesADifferentHeader) {
    std::ofstream(path_) << "time,other\n0,1\n";
    try {
        qs::SeriesWriter series(path_, columns_, true, 1.0);
        FAIL() << "expected qs::Error";
    } catch (const qs::Error& e) {
        EXPECT_NE(std::string(e.what()).find(path_), std::string::npos) << e.what();
    }
    EXPECT_EQ(content(), "time,other\n0,1\n");  // untouched
}

TEST_F(SeriesWriterTest, ResumeWithoutAFileStartsAfresh) {
    {
        qs::SeriesWriter series(path_, columns_, true, 5.0);
        series.write({5.0, 1.0, 2.0});
    }
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n5,1,2\n");
}

TEST_F(SeriesWriterTest, AppendFalseTruncates) {
    std::ofstream(path_) << "time,gate_flux,q_mid\n0,1,2\n";
    qs::SeriesWriter series(path_, columns_, false, 0.0);
    EXPECT_EQ(content(), "time,gate_flux,q_mid\n");
}
