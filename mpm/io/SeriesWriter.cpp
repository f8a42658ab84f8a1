#include "io/SeriesWriter.hpp"

#include <unistd.h>

#include "core/Error.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace qs {

namespace {

std::string systemReason() { return errno ? std::string(": ") + std::strerror(errno) : std::string(); }

/// Splits a CSV line without quoting (our writer never quotes: names and numbers only).
std::vector<std::string> splitLine(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return cells;
}

/// True if text is one whole number as written by %.9g (or nan/inf), with nothing after it.
bool parseNumber(const std::string& text, double& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

}  // namespace

SeriesWriter::SeriesWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns) {
    checkColumns();
    openFresh();
}

SeriesWriter::SeriesWriter(const std::string& path, const std::vector<std::string>& columns, bool append,
                           double resumeTime)
    : path_(path), columns_(columns) {
    checkColumns();
    if (append) openForResume(resumeTime);
    else openFresh();
}

SeriesWriter::~SeriesWriter() {
    if (file_) std::fclose(file_);
}

void SeriesWriter::checkColumns() const {
    QS_CHECK(!columns_.empty(), path_ << ": a series needs at least one column");
    for (const std::string& c : columns_)
        QS_CHECK(!c.empty() && c.find_first_of(",\"\r\n") == std::string::npos,
                 path_ << ": column name '" << c << "' must be non-empty, without ',', '\"' or line breaks");
}

std::string SeriesWriter::headerLine() const {
    std::string line;
    for (std::size_t i = 0; i < columns_.size(); ++i) line += (i ? "," : "") + columns_[i];
    return line;
}

void SeriesWriter::openFresh() {
    errno = 0;
    file_ = std::fopen(path_.c_str(), "w");
    if (!file_) throw Error(path_ + ": cannot open series file for writing" + systemReason());
    if (std::fprintf(file_, "%s\n", headerLine().c_str()) < 0 || std::fflush(file_) != 0)
        throw Error(path_ + ": cannot write the header" + systemReason());
}

void SeriesWriter::openForResume(double resumeTime) {
    std::error_code error;
    if (!std::filesystem::exists(path_, error) || std::filesystem::file_size(path_, error) == 0) {
        openFresh();
        return;
    }
    std::ifstream in(path_);
    if (!in) throw Error(path_ + ": cannot open series file to resume it");
    std::string header;
    std::getline(in, header);
    if (!header.empty() && header.back() == '\r') header.pop_back();
    QS_CHECK(header == headerLine(), path_ << ": cannot resume: its columns are\n  " << header
                                           << "\nbut this run writes\n  " << headerLine()
                                           << "\n(move the old file away or start without resuming)");

    // Times are printed with 9 significant digits, so a time equal to resumeTime may read back
    // slightly above it: allow that much.
    const double limit = resumeTime + 1e-8 * std::max(1.0, std::fabs(resumeTime));
    std::vector<std::string> kept;
    std::string line;
    while (std::getline(in, line)) {
        const bool complete = !in.eof();  // the last line of a crashed run may lack its newline
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::vector<std::string> cells = splitLine(line);
        if (!complete || cells.size() != columns_.size()) continue;
        bool numeric = true;
        std::vector<double> values(cells.size());
        for (std::size_t i = 0; i < cells.size() && numeric; ++i) numeric = parseNumber(cells[i], values[i]);
        if (numeric && values[0] <= limit) kept.push_back(line);
    }
    in.close();

    // Rewrite through a temporary and a rename, so a crash now cannot lose the kept lines.
    const std::string temporary = path_ + ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        if (!out) throw Error(temporary + ": cannot open for writing");
        out << header << '\n';
        for (const std::string& k : kept) out << k << '\n';
        errno = 0;
        out.flush();
        if (!out) {
            const std::string reason = systemReason();
            out.close();
            std::filesystem::remove(temporary, error);
            throw Error(temporary + ": cannot write" + reason + "; " + path_ + " is left as it was");
        }
    }
    std::filesystem::rename(temporary, path_, error);
    if (error) throw Error(path_ + ": cannot replace with " + temporary + ": " + error.message());

    errno = 0;
    file_ = std::fopen(path_.c_str(), "a");
    if (!file_) throw Error(path_ + ": cannot open series file for appending" + systemReason());
}

void SeriesWriter::write(const std::vector<double>& row) {
    QS_CHECK(row.size() == columns_.size(),
             path_ << ": a row has " << columns_.size() << " values (" << headerLine() << "), got " << row.size());
    std::string line;
    char number[32];
    for (std::size_t i = 0; i < row.size(); ++i) {
        std::snprintf(number, sizeof number, "%.9g", row[i]);
        if (i) line += ',';
        line += number;
    }
    line += '\n';
    // Flushed per line: the series of a running or crashed simulation can be plotted. A line
    // that cannot be written whole (a full disk) is cut off again, so the file keeps only
    // complete lines.
    const long before = std::ftell(file_);
    errno = 0;
    if (std::fputs(line.c_str(), file_) < 0 || std::fflush(file_) != 0) {
        const std::string reason = systemReason();
        std::clearerr(file_);
        if (before >= 0 && ::ftruncate(::fileno(file_), before) == 0) std::fseek(file_, before, SEEK_SET);
        throw Error(path_ + ": cannot write a line" + reason + "; the file keeps the complete lines before it");
    }
}

}  // namespace qs
