#include "io/FieldWriter.hpp"

#include <cstring>

#include <cerrno>

#include "core/Error.hpp"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace qs {

namespace {

const char* const kHdf5FileName = "fields.h5";
const char* const kXdmfFileName = "fields.xdmf";

/// Owns one HDF5 identifier and releases it with the matching close function, so that every
/// early exit by exception leaves no object open (an open object keeps the file open).
class Hdf5Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Hdf5Handle() = default;
    Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
        if (this != &other) {
            reset();
            std::swap(id_, other.id_);
            closer_ = other.closer_;
        }
        return *this;
    }
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;
    ~Hdf5Handle() { reset(); }

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    /// Closes now and reports whether closing succeeded (closing a file flushes it).
    bool close() {
        bool ok = true;
        if (id_ >= 0 && closer_) ok = closer_(id_) >= 0;
        id_ = -1;
        return ok;
    }
    void reset() { close(); }

private:
    hid_t id_ = -1;
    Closer closer_ = nullptr;
};

/// The most specific message on HDF5's error stack, to make our own message concrete.
std::string hdf5Reason() {
    std::string reason;
    auto collect = [](unsigned, const H5E_error2_t* error, void* data) -> herr_t {
        if (error && error->desc && *error->desc) *static_cast<std::string*>(data) = error->desc;
        return 0;
    };
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect, &reason);
    return reason.empty() ? std::string() : " (HDF5: " + reason + ")";
}

[[noreturn]] void fail(const std::string& file, const std::string& operation) {
    throw Error(file + ": cannot " + operation + hdf5Reason());
}

/// Names become HDF5 link names and XML attribute values: keep them to a safe alphabet rather
/// than escape them twice.
bool isSafeName(const std::string& name) {
    if (name.empty()) return false;
    for (char c : name) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '_' || c == '-' || c == '.';
        if (!ok) return false;
    }
    return true;
}

std::string formatDouble(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string stepGroupName(int index) {
    char text[32];
    std::snprintf(text, sizeof text, "step_%06d", index);
    return text;
}

/// Copies count points of `dimension` components into 3 components, the vertical (last) axis
/// going to Z: 1D z -> (0,0,z), 2D (x,z) -> (x,0,z), 3D unchanged.
void padToXyz(const double* in, std::size_t count, int dimension, std::vector<double>& out) {
    static const int target[3][3] = {{2, -1, -1}, {0, 2, -1}, {0, 1, 2}};
    out.assign(count * 3, 0.0);
    const int* map = target[dimension - 1];
    for (std::size_t p = 0; p < count; ++p)
        for (int d = 0; d < dimension; ++d) out[3 * p + map[d]] = in[dimension * p + d];
}

enum class StoredKind { Scalar, Vector, SymmetricTensor, Matrix };

const char* xdmfAttributeType(StoredKind kind) {
    switch (kind) {
        case StoredKind::Scalar: return "Scalar";
        case StoredKind::Vector: return "Vector";
        case StoredKind::SymmetricTensor: return "Tensor6";
        case StoredKind::Matrix: return "Matrix";
    }
    return "Scalar";
}

}  // namespace

struct FieldWriter::Impl {
    struct AttributeRecord {
        std::string name;
        StoredKind kind;
        int columns;  // 1 for a scalar, else the second dimension of the dataset
    };
    struct SetRecord {
        std::string name;
        std::size_t count;
        std::vector<AttributeRecord> attributes;
    };
    struct StepRecord {
        double time;
        std::string group;
        std::vector<SetRecord> sets;
    };

    std::string hdf5Path;
    std::string xdmfPath;
    int dimension = 0;
    Hdf5Handle file;
    Hdf5Handle stepGroup;
    bool stepOpen = false;
    std::vector<StepRecord> steps;
    std::vector<double> padded;  // reused between calls to avoid reallocating each step

    void writeRootAttribute();
    void writeDoubleAttribute(hid_t object, const std::string& objectPath, const char* name, double value);
    void writeStringAttribute(hid_t object, const std::string& objectPath, const char* name,
                              const std::string& value);
    void writeDataset(hid_t group, const std::string& groupPath, const std::string& name,
                      const void* data, hid_t memoryType, hid_t fileType, std::size_t rows, int columns,
                      const char* components);
    void writeXdmf() const;
    std::string xdmfText() const;
};

void FieldWriter::Impl::writeDoubleAttribute(hid_t object, const std::string& objectPath,
                                             const char* name, double value) {
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose);
    if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0)
        fail(hdf5Path, "write attribute " + objectPath + "@" + name);
}

void FieldWriter::Impl::writeStringAttribute(hid_t object, const std::string& objectPath,
                                             const char* name, const std::string& value) {
    Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.valid() || H5Tset_size(type.get(), value.size() + 1) < 0)
        fail(hdf5Path, "make a string type for attribute " + objectPath + "@" + name);
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose);
    if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), type.get(), value.c_str()) < 0)
        fail(hdf5Path, "write attribute " + objectPath + "@" + name);
}

void FieldWriter::Impl::writeRootAttribute() {
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(
        H5Acreate2(file.get(), "dimension", H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT, &dimension) < 0)
        fail(hdf5Path, "write attribute /@dimension");
}

void FieldWriter::Impl::writeDataset(hid_t group, const std::string& groupPath, const std::string& name,
                                     const void* data, hid_t memoryType, hid_t fileType, std::size_t rows,
                                     int columns, const char* components) {
    const std::string path = groupPath + "/" + name;
    const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
    Hdf5Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose);
    if (!space.valid()) fail(hdf5Path, "make the dataspace of " + path);
    Hdf5Handle dataset(
        H5Dcreate2(group, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose);
    if (!dataset.valid()) fail(hdf5Path, "create dataset " + path);
    // A zero-sized dataset needs no write (and HDF5 would reject the null buffer).
    if (rows > 0 && H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail(hdf5Path, "write dataset " + path);
    if (components) writeStringAttribute(dataset.get(), path, "components", components);
}

std::string FieldWriter::Impl::xdmfText() const {
    const std::string h5 = kHdf5FileName;  // relative: the .xdmf sits beside the .h5
    std::ostringstream x;
    x << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"points\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const StepRecord& step : steps) {
        x << "      <Grid Name=\"" << step.group << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
          << "        <Time Value=\"" << formatDouble(step.time) << "\"/>\n";
        for (const SetRecord& set : step.sets) {
            if (set.count == 0) continue;  // zero-sized DataItems break the readers
            const std::string base = h5 + ":/" + step.group + "/" + set.name + "/";
            const std::string n = std::to_string(set.count);
            x << "        <Grid Name=\"" << set.name << "\" GridType=\"Uniform\">\n"
              << "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
              << "\" NodesPerElement=\"1\">\n"
              << "            <DataItem Dimensions=\"" << n
              << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << base << "connectivity</DataItem>\n"
              << "          </Topology>\n"
              << "          <Geometry GeometryType=\"XYZ\">\n"
              << "            <DataItem Dimensions=\"" << n
              << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base << "positions</DataItem>\n"
              << "          </Geometry>\n";
            for (const AttributeRecord& a : set.attributes) {
                const std::string dims = a.columns == 1 ? n : n + " " + std::to_string(a.columns);
                x << "          <Attribute Name=\"" << a.name << "\" AttributeType=\"" << xdmfAttributeType(a.kind)
                  << "\" Center=\"Node\">\n"
                  << "            <DataItem Dimensions=\"" << dims
                  << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base << a.name << "</DataItem>\n"
                  << "          </Attribute>\n";
            }
            x << "        </Grid>\n";
        }
        x << "      </Grid>\n";
    }
    x << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
    return x.str();
}

void FieldWriter::Impl::writeXdmf() const {
    // Write beside, then rename: a reader (or a crash) never sees a half-written file.
    const std::string temporary = xdmfPath + ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        if (!out) throw Error(temporary + ": cannot open for writing");
        errno = 0;
        out << xdmfText();
        out.flush();
        if (!out) {
            const std::string reason = errno ? std::string(": ") + std::strerror(errno) : std::string();
            out.close();
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw Error(temporary + ": cannot write" + reason + "; " + xdmfPath + " is left as it was");
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, xdmfPath, error);
    if (error) throw Error(xdmfPath + ": cannot replace with " + temporary + ": " + error.message());
}

FieldWriter::FieldWriter(const std::string& directory, int dimension) : impl_(std::make_unique<Impl>()) {
    QS_CHECK(dimension >= 1 && dimension <= 3,
             "FieldWriter: dimension must be 1, 2 or 3, got " << dimension);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // we report errors ourselves, as qs::Error
    const std::filesystem::path dir = std::filesystem::path(directory.empty() ? std::string(".") : directory);
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) throw Error(directory + ": cannot create output directory: " + error.message());

    hdf5Path_ = (dir / kHdf5FileName).string();
    xdmfPath_ = (dir / kXdmfFileName).string();
    impl_->hdf5Path = hdf5Path_;
    impl_->xdmfPath = xdmfPath_;
    impl_->dimension = dimension;
    impl_->file = Hdf5Handle(H5Fcreate(hdf5Path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!impl_->file.valid()) fail(hdf5Path_, "create file");
    impl_->writeRootAttribute();
    if (H5Fflush(impl_->file.get(), H5F_SCOPE_GLOBAL) < 0) fail(hdf5Path_, "flush file");
    // Between outputs the file is closed: a crash then finds it complete, and HDF5's metadata
    // cache, which grows with the file while it is open (from 17 to 32 MiB of resident memory
    // over 200 outputs), is given back every time.
    if (!impl_->file.close()) fail(hdf5Path_, "close file");
    impl_->writeXdmf();
}

FieldWriter::~FieldWriter() {
    if (!impl_) return;
    try {
        if (impl_->stepOpen) endStep();
    } catch (...) {
        // A destructor must not throw; the last complete step stays readable.
    }
    impl_->stepGroup.close();
    impl_->file.close();
}

int FieldWriter::stepsWritten() const {
    return static_cast<int>(impl_->steps.size()) - (impl_->stepOpen ? 1 : 0);
}

void FieldWriter::beginStep(double time) {
    Impl& s = *impl_;
    QS_CHECK(!s.stepOpen, hdf5Path_ << ": beginStep(" << time << ") while the step at t = "
                                    << s.steps.back().time << " s is still open (call endStep first)");
    const std::string group = stepGroupName(static_cast<int>(s.steps.size()));
    s.file = Hdf5Handle(H5Fopen(hdf5Path_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
    if (!s.file.valid()) fail(hdf5Path_, "reopen file to add the step at t = " + std::to_string(time) + " s");
    s.stepGroup = Hdf5Handle(H5Gcreate2(s.file.get(), group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                             H5Gclose);
    if (!s.stepGroup.valid()) fail(hdf5Path_, "create group /" + group);
    s.writeDoubleAttribute(s.stepGroup.get(), "/" + group, "time", time);
    s.steps.push_back({time, group, {}});
    s.stepOpen = true;
}

void FieldWriter::writePointSet(const std::string& setName, std::size_t count, const double* positions,
                                const std::vector<PointField>& fields) {
    Impl& s = *impl_;
    QS_CHECK(s.stepOpen, hdf5Path_ << ": writePointSet('" << setName << "') outside a step (call beginStep first)");
    QS_CHECK(isSafeName(setName), hdf5Path_ << ": point set name '" << setName
                                            << "' must be non-empty letters, digits, '_', '-' or '.'");
    Impl::StepRecord& step = s.steps.back();
    for (const Impl::SetRecord& set : step.sets)
        QS_CHECK(set.name != setName, hdf5Path_ << ": point set '" << setName << "' written twice at t = "
                                                << step.time << " s");
    QS_CHECK(count == 0 || positions, hdf5Path_ << ": point set '" << setName << "': positions are null");

    // Validate every field before writing anything, so a bad call leaves no half set behind.
    const int D = s.dimension;
    std::vector<Impl::AttributeRecord> attributes;
    for (const PointField& f : fields) {
        const std::string where = hdf5Path_ + ": point set '" + setName + "', field '" + f.name + "': ";
        QS_CHECK(isSafeName(f.name) && f.name != "positions" && f.name != "connectivity",
                 where << "the name must be letters, digits, '_', '-' or '.', and not 'positions' or "
                          "'connectivity'");
        for (const Impl::AttributeRecord& a : attributes)
            QS_CHECK(a.name != f.name, where << "given twice");
        QS_CHECK(f.components >= 1, where << "components must be >= 1, got " << f.components);
        QS_CHECK(count == 0 || f.data, where << "data is null");
        StoredKind kind = StoredKind::Matrix;
        switch (f.kind) {
            case FieldKind::Automatic:
                if (f.components == 1) kind = StoredKind::Scalar;
                else if (f.components == 6) kind = StoredKind::SymmetricTensor;
                else if (f.components == D) kind = StoredKind::Vector;
                break;
            case FieldKind::Scalar:
                QS_CHECK(f.components == 1, where << "a scalar has 1 component, got " << f.components);
                kind = StoredKind::Scalar;
                break;
            case FieldKind::Vector:
                QS_CHECK(f.components == D, where << "a vector has " << D << " components (the dimension), got "
                                                  << f.components);
                kind = StoredKind::Vector;
                break;
            case FieldKind::SymmetricTensor:
                QS_CHECK(f.components == 6, where << "a symmetric tensor has 6 components, got " << f.components);
                kind = StoredKind::SymmetricTensor;
                break;
        }
        const int columns = kind == StoredKind::Vector ? 3 : f.components;
        attributes.push_back({f.name, kind, columns});
    }

    const std::string groupPath = "/" + step.group + "/" + setName;
    Hdf5Handle group(H5Gcreate2(s.stepGroup.get(), setName.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Gclose);
    if (!group.valid()) fail(hdf5Path_, "create group " + groupPath);

    if (count > 0) padToXyz(positions, count, D, s.padded);
    s.writeDataset(group.get(), groupPath, "positions", s.padded.data(), H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE,
                   count, 3, "x y z");

    std::vector<std::int32_t> ids(count);
    QS_CHECK(count <= static_cast<std::size_t>(INT32_MAX),
             hdf5Path_ << ": point set '" << setName << "' has more than 2^31 points");
    for (std::size_t p = 0; p < count; ++p) ids[p] = static_cast<std::int32_t>(p);
    s.writeDataset(group.get(), groupPath, "connectivity", ids.data(), H5T_NATIVE_INT32, H5T_STD_I32LE, count,
                   1, nullptr);

    for (std::size_t i = 0; i < fields.size(); ++i) {
        const PointField& f = fields[i];
        const Impl::AttributeRecord& a = attributes[i];
        const double* data = f.data;
        const char* components = nullptr;
        if (a.kind == StoredKind::Vector) {
            if (count > 0) padToXyz(f.data, count, D, s.padded);
            data = s.padded.data();
            components = "x y z";
        } else if (a.kind == StoredKind::SymmetricTensor) {
            components = "xx yy zz yz xz xy";
        }
        s.writeDataset(group.get(), groupPath, f.name, data, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, count, a.columns,
                       components);
    }
    step.sets.push_back({setName, count, std::move(attributes)});
}

void FieldWriter::endStep() {
    Impl& s = *impl_;
    QS_CHECK(s.stepOpen, hdf5Path_ << ": endStep() without beginStep()");
    s.stepOpen = false;
    s.stepGroup.close();
    if (H5Fflush(s.file.get(), H5F_SCOPE_GLOBAL) < 0) fail(hdf5Path_, "flush file");
    if (!s.file.close()) fail(hdf5Path_, "close file");
    s.writeXdmf();
}

}  // namespace qs
