#pragma once
// Support for the study tests (tools/study.py): a study folder in the build tree, running the
// study tool and the quicksand command as a user types them, and reading study.csv.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace qs::test {

namespace fs = std::filesystem;

/// A fresh folder for one test's study (its study.toml and output/)
inline fs::path freshStudyFolder(const std::string& tag) {
    const fs::path dir = fs::path(QUICKSAND_BINARY_DIR) / "study-tests" / tag;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

inline std::string readText(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline std::string quoted(const std::string& s) { return "'" + s + "'"; }

struct Command {
    int exitCode = -1;
    std::string output;  ///< stdout and stderr together
};

/// Runs a shell command, its output captured
inline Command runCommand(const std::string& command) {
    Command r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

/// tools/study.py on a study file, with the quicksand of this build
inline std::string studyCommand(const fs::path& studyFile, const std::string& options = "--no-plots --quiet") {
    return std::string("QUICKSAND=") + QUICKSAND_EXECUTABLE + " " + QUICKSAND_PYTHON + " " + QUICKSAND_SOURCE_DIR +
           "/tools/study.py " + quoted(studyFile.string()) + " " + options;
}

inline Command runStudy(const fs::path& studyFile, const std::string& options = "--no-plots --quiet") {
    return runCommand(studyCommand(studyFile, options));
}

/// study.csv as rows of column -> text
inline std::vector<std::map<std::string, std::string>> readStudyCsv(const fs::path& file) {
    std::vector<std::map<std::string, std::string>> rows;
    std::ifstream in(file);
    std::string line;
    std::vector<std::string> header;
    auto split = [](const std::string& l) {
        // the tool writes lists as JSON in quotes; the tests' parameters are plain numbers and words
        std::vector<std::string> cells;
        std::string cell;
        bool quotedCell = false;
        for (char c : l) {
            if (c == '"') quotedCell = !quotedCell;
            else if (c == ',' && !quotedCell) {
                cells.push_back(cell);
                cell.clear();
            } else if (c != '\r') cell += c;
        }
        cells.push_back(cell);
        return cells;
    };
    while (std::getline(in, line)) {
        const auto cells = split(line);
        if (header.empty()) {
            header = cells;
            continue;
        }
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k) row[header[k]] = cells[k];
        rows.push_back(row);
    }
    return rows;
}

}  // namespace qs::test
