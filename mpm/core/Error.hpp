#pragma once
// Two kinds of check (as in MFEM's MFEM_VERIFY / MFEM_ASSERT):
//  - QS_CHECK: always on; for input and for conditions a user can cause. Throws qs::Error.
//  - QS_ASSERT: debug builds only; for internal invariants, the only kind allowed in hot loops.
#include <cassert>
#include <sstream>
#include <stdexcept>
#include <string>

namespace qs {

/// Any error quicksand reports to the user. The message is complete: it names what is wrong,
/// where (file, line, key when known) and what was expected.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// An error that every rank of an MPI run throws together, having agreed on it (the lowest
/// rank's that met it): said once, by rank 0; no rank is left waiting, so none is aborted.
class SharedError : public Error {
public:
    using Error::Error;
};

/// An error in a case file: carries file, line and key so the message can point at them.
class InputError : public Error {
public:
    InputError(const std::string& file, int line, const std::string& key, const std::string& what)
        : Error(format(file, line, key, what)), file_(file), line_(line), key_(key), detail_(what) {}
    const std::string& file() const { return file_; }
    /// what is wrong, without the file, line and key
    const std::string& detail() const { return detail_; }
    int line() const { return line_; }
    const std::string& key() const { return key_; }

private:
    static std::string format(const std::string& file, int line, const std::string& key,
                              const std::string& what) {
        std::ostringstream s;
        s << file;
        if (line > 0) s << ":" << line;
        s << ": ";
        if (!key.empty()) s << "key '" << key << "': ";
        s << what;
        return s.str();
    }
    std::string file_;
    int line_;
    std::string key_;
    std::string detail_;
};

}  // namespace qs

#define QS_CHECK(cond, msg)                                       \
    do {                                                          \
        if (!(cond)) {                                            \
            std::ostringstream qs_check_stream_;                  \
            qs_check_stream_ << msg;                              \
            throw ::qs::Error(qs_check_stream_.str());            \
        }                                                         \
    } while (0)

#define QS_ASSERT(cond) assert(cond)
