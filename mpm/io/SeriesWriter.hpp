#pragma once
// SeriesWriter: a time series as CSV (OUTDIR/series.csv), one line per output time.
//
// Usage:
//   SeriesWriter series(path, {"time", "gate_flux", ...});        // new file, header written
//   series.write({t, q, ...});                                    // one line, flushed
// Resuming from a checkpoint taken at time tc:
//   SeriesWriter series(path, columns, /*append=*/true, tc);      // keeps lines with time <= tc
//
// Format: a header line of column names, then values separated by ',' printed with %.9g (enough
// for plotting and comparisons to 1e-8 relative; the checkpoint, not the CSV, holds exact state).
// Each line is flushed as it is written, so a crashed or running simulation can be plotted.
// The first column is the time (s); units of the others are the caller's (docs/case-format.md).
#include <cstdio>
#include <string>
#include <vector>

namespace qs {

class SeriesWriter {
public:
    /// Creates (truncates) path and writes the header. Throws qs::Error naming path if it cannot
    /// open or write, or if a column name is empty or contains ',', '"' or a line break.
    SeriesWriter(const std::string& path, const std::vector<std::string>& columns);

    /// append = false: as above. append = true: continues an existing file after a resume. Keeps
    /// the existing data lines whose first column (time, s) is <= resumeTime (within a relative
    /// 1e-8, the precision of %.9g), drops later ones and any line that is incomplete or not all
    /// numbers (a crash can leave half a line), then writes after them. The existing header must
    /// name the same columns (qs::Error otherwise: mixing layouts would corrupt the series). A
    /// missing or empty file is started afresh.
    SeriesWriter(const std::string& path, const std::vector<std::string>& columns, bool append,
                 double resumeTime);

    ~SeriesWriter();
    SeriesWriter(const SeriesWriter&) = delete;
    SeriesWriter& operator=(const SeriesWriter&) = delete;

    /// Writes one line. Pre: row.size() == number of columns (qs::Error otherwise).
    void write(const std::vector<double>& row);

    const std::string& path() const { return path_; }
    const std::vector<std::string>& columns() const { return columns_; }

private:
    void checkColumns() const;
    void openFresh();
    void openForResume(double resumeTime);
    std::string headerLine() const;

    std::string path_;
    std::vector<std::string> columns_;
    std::FILE* file_ = nullptr;
};

}  // namespace qs
