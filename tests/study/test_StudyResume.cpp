// An interrupted study resumes (labels `study` and `resume`): Ctrl-C (SIGINT) to tools/study.py
// stops every running variant after its checkpoint; the same command again keeps the finished
// variants, continues the interrupted ones from their checkpoints, and ends with the same
// study.csv as a study that was never interrupted.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "StudyTestSupport.hpp"

using namespace qs::test;

namespace {

void writeStudy(const fs::path& dir) {
    const std::string base = std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/falling_head";
    std::ofstream(dir / "study.toml") << "base = \"" << base << "\"\nthreads = 1\nparallel = 1\n"
                                      << "[parameters]\n\"reservoir.area\" = [5.0e-5, 7.0e-5, 1.0e-4]\n"
                                      << "[set]\n\"time.end\" = 3.0\n\"output.fields\" = false\n"
                                      << "\"time.checkpoint_interval\" = 0.5\n";
}

}  // namespace

TEST(StudyResume, AnInterruptedStudyEndsWithTheStudyCsvOfAnUninterruptedOne) {
    const fs::path whole = freshStudyFolder("resume-whole");
    writeStudy(whole);
    const Command once = runStudy(whole / "study.toml");
    ASSERT_EQ(once.exitCode, 0) << once.output;

    const fs::path cut = freshStudyFolder("resume-cut");
    writeStudy(cut);
    // start the study, and interrupt it once the second variant has written a checkpoint
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        setpgid(0, 0);
        execl("/bin/sh", "sh", "-c", ("exec env " + studyCommand(cut / "study.toml") + " > " + (cut / "first.log").string() + " 2>&1").c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    const fs::path second = cut / "output" / "02_area=7e-05" / "checkpoint.h5";
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    bool ended = false;
    while (!fs::exists(second) && std::chrono::steady_clock::now() - start < std::chrono::seconds(300)) {
        if (waitpid(pid, &status, WNOHANG) == pid) {
            ended = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_FALSE(ended) << "the study ended before it could be interrupted:\n" << readText(cut / "first.log");
    ASSERT_TRUE(fs::exists(second)) << readText(cut / "first.log");
    kill(pid, SIGINT);
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << readText(cut / "first.log");
    EXPECT_EQ(WEXITSTATUS(status), 130) << readText(cut / "first.log");
    EXPECT_TRUE(fs::exists(cut / "output" / "01_area=5e-05" / "study-status.json")) << "the first variant finished";
    EXPECT_FALSE(fs::exists(cut / "output" / "02_area=7e-05" / "study-status.json")) << "the second was interrupted";
    EXPECT_FALSE(fs::exists(cut / "output" / "03_area=0.0001")) << "the third never started";
    const std::string firstSeries = readText(cut / "output" / "01_area=5e-05" / "series.csv");

    const Command again = runStudy(cut / "study.toml", "--no-plots");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find("1 done before, 2 to run"), std::string::npos) << again.output;
    EXPECT_EQ(readText(cut / "output" / "01_area=5e-05" / "series.csv"), firstSeries) << "a finished variant is kept";
    EXPECT_NE(readText(cut / "output" / "02_area=7e-05.log").find("--resume"), std::string::npos)
        << "the interrupted variant continues from its checkpoint";
    EXPECT_EQ(readText(cut / "output" / "study.csv"), readText(whole / "output" / "study.csv"));
    for (const char* v : {"01_area=5e-05", "02_area=7e-05", "03_area=0.0001"})
        EXPECT_EQ(readText(cut / "output" / v / "series.csv"), readText(whole / "output" / v / "series.csv")) << v;
}
