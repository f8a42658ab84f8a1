#include "io/FieldWriter.hpp"

#include <chrono>
#include <cstring>

#include <cerrno>

#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "io/Hdf5File.hpp"

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
const char* const kStepDirectoryName = "fields";  // one file per output step, beside fields.h5

[[noreturn]] void fail(const std::string& file, const std::string& operation) { failHdf5(file, operation); }

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

/// step_NNNNNN.h5 or step_NNNNNN.h5.tmp: the only files a new or resumed series removes.
bool isStepFileName(const std::string& name) {
    const std::string stem = name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0
                                 ? name.substr(0, name.size() - 4) : name;
    if (stem.size() != 14 || stem.compare(0, 5, "step_") != 0 || stem.compare(11, 3, ".h5") != 0) return false;
    for (int k = 5; k < 11; ++k)
        if (stem[k] < '0' || stem[k] > '9') return false;
    return true;
}

/// Group (or file) creation properties that keep the links in the order they were made, so that
/// a resumed run reads a step's sets and fields back in the order they were written.
Hdf5Handle creationOrdered(hid_t propertyClass) {
    Hdf5Handle properties(H5Pcreate(propertyClass), H5Pclose);
    if (properties.valid()) H5Pset_link_creation_order(properties.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
    return properties;
}

/// How a point set's dataset was written, read back from its "components" attribute when a
/// resumed run takes over the steps already on disk.
StoredKind storedKindOf(const std::string& components, int columns) {
    if (components == "x y z") return StoredKind::Vector;
    if (components == "xx yy zz yz xz xy") return StoredKind::SymmetricTensor;
    return columns == 1 ? StoredKind::Scalar : StoredKind::Matrix;
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
        std::string group;  // step_NNNNNN: the link in fields.h5 and the file fields/step_NNNNNN.h5
        std::vector<SetRecord> sets;
    };

    std::string hdf5Path;
    std::string xdmfPath;
    std::filesystem::path stepDirectory;
    int dimension = 0;
    Hdf5Handle stepFile;       // open from beginStep to endStep, under its temporary name
    Hdf5Handle stepGroup;      // the step file's root group
    std::string stepTemporary;
    bool stepOpen = false;
    std::vector<StepRecord> steps;
    std::vector<double> padded;  // reused between calls to avoid reallocating each step
    bool unsynced = false;                   // files published since the last makeDurable
    double listingInterval = 0;              // s of wall time between listings, 0: every step
    std::chrono::steady_clock::time_point lastListing;
    bool listingPending = false;             // steps ended but not yet listed
    std::size_t indexedSteps = 0;            // the steps the published fields.h5 links
    std::string xdmfBody;                    // fields.xdmf's text of steps[0, xdmfSteps)
    std::size_t xdmfSteps = 0;

    std::string stepPath(const std::string& group) const { return (stepDirectory / (group + ".h5")).string(); }
    void writeDimensionAttribute(hid_t file, const std::string& path);
    void writeDoubleAttribute(hid_t object, const std::string& objectPath, const char* name, double value);
    void writeStringAttribute(hid_t object, const std::string& objectPath, const char* name,
                              const std::string& value);
    void writeDataset(hid_t group, const std::string& groupPath, const std::string& name,
                      const void* data, hid_t memoryType, hid_t fileType, std::size_t rows, int columns,
                      const char* components);
    void writeIndex();
    void publishIndex(bool extend, std::size_t listed);
    void publishListing();
    void writeXdmf();
    static std::string xdmfStep(const StepRecord& step);
    bool readStep(const std::string& group, double keepBefore, StepRecord& step) const;
};

void FieldWriter::Impl::writeDoubleAttribute(hid_t object, const std::string& objectPath,
                                             const char* name, double value) {
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose);
    if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0)
        fail(stepTemporary, "write attribute " + objectPath + "@" + name);
}

void FieldWriter::Impl::writeStringAttribute(hid_t object, const std::string& objectPath,
                                             const char* name, const std::string& value) {
    Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!type.valid() || H5Tset_size(type.get(), value.size() + 1) < 0)
        fail(stepTemporary, "make a string type for attribute " + objectPath + "@" + name);
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose);
    if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), type.get(), value.c_str()) < 0)
        fail(stepTemporary, "write attribute " + objectPath + "@" + name);
}

void FieldWriter::Impl::writeDimensionAttribute(hid_t file, const std::string& path) {
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle attribute(H5Acreate2(file, "dimension", H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                         H5Aclose);
    if (!space.valid() || !attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT, &dimension) < 0)
        fail(path, "write attribute /@dimension");
    // which build wrote the file (core/BuildInfo.hpp): a bug report's first question
    writeStringAttribute(file, "/", "quicksand", buildLine());
}

void FieldWriter::Impl::writeDataset(hid_t group, const std::string& groupPath, const std::string& name,
                                     const void* data, hid_t memoryType, hid_t fileType, std::size_t rows,
                                     int columns, const char* components) {
    const std::string path = groupPath + "/" + name;
    const hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
    Hdf5Handle space(H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr), H5Sclose);
    if (!space.valid()) fail(stepTemporary, "make the dataspace of " + path);
    Hdf5Handle dataset(
        H5Dcreate2(group, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose);
    if (!dataset.valid()) fail(stepTemporary, "create dataset " + path);
    // A zero-sized dataset needs no write (and HDF5 would reject the null buffer).
    if (rows > 0 && H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail(stepTemporary, "write dataset " + path);
    if (components) writeStringAttribute(dataset.get(), path, "components", components);
}

void FieldWriter::Impl::writeIndex() {
    // fields.h5 holds no data, only a link per step to its file: readers (h5py, ParaView, the
    // HDF5 C API) see one file with groups /step_NNNNNN, and HDF5 finds each linked file relative
    // to fields.h5's own directory. It is replaced only by rename. The last one published is
    // copied and the new steps' links added to the copy (creating every link anew each output
    // was most of a 1D run's output time); if that fails, it is written whole.
    const std::size_t listed = steps.size() - (stepOpen ? 1 : 0);
    if (indexedSteps > 0 && indexedSteps <= listed) {
        try {
            publishIndex(true, listed);
            return;
        } catch (const Error&) {
            // a fields.h5 changed or damaged since: write it whole
        }
    }
    publishIndex(false, listed);
}

void FieldWriter::Impl::publishIndex(bool extend, std::size_t listed) {
    const std::string temporary = hdf5Path + ".tmp";
    try {
        if (extend) {
            std::error_code error;
            std::filesystem::copy_file(hdf5Path, temporary, std::filesystem::copy_options::overwrite_existing, error);
            if (error) throw Error(hdf5Path + ": cannot copy to " + temporary + ": " + error.message());
        }
        Hdf5Handle file(extend ? H5Fopen(temporary.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)
                               : H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                        H5Fclose);
        if (!file.valid()) fail(temporary, extend ? "open the copy of " + hdf5Path : "create file");
        if (!extend) writeDimensionAttribute(file.get(), temporary);
        for (std::size_t k = extend ? indexedSteps : 0; k < listed; ++k) {
            const std::string target = std::string(kStepDirectoryName) + "/" + steps[k].group + ".h5";
            if (H5Lcreate_external(target.c_str(), "/", file.get(), steps[k].group.c_str(), H5P_DEFAULT,
                                   H5P_DEFAULT) < 0)
                fail(temporary, "link /" + steps[k].group + " to " + target);
        }
        if (!file.close()) fail(temporary, "close file");
        publishFile(temporary, hdf5Path, Durability::Deferred);
        indexedSteps = listed;
        unsynced = true;
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

namespace {
const char* const kXdmfHead =
    "<?xml version=\"1.0\" ?>\n"
    "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
    "  <Domain>\n"
    "    <Grid Name=\"points\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
const char* const kXdmfTail =
    "    </Grid>\n"
    "  </Domain>\n"
    "</Xdmf>\n";
}  // namespace

// fields.h5 and fields.xdmf listing every step ended
void FieldWriter::Impl::publishListing() {
    listingPending = true;  // until both are published
    writeIndex();
    writeXdmf();
    lastListing = std::chrono::steady_clock::now();
    listingPending = false;
}

// One step's entry in fields.xdmf: a spatial collection of its point sets.
std::string FieldWriter::Impl::xdmfStep(const StepRecord& step) {
    std::ostringstream x;
    x << "      <Grid Name=\"" << step.group << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "        <Time Value=\"" << formatDouble(step.time) << "\"/>\n";
    for (const SetRecord& set : step.sets) {
        if (set.count == 0) continue;  // zero-sized DataItems break the readers
        const std::string base = std::string(kStepDirectoryName) + "/" + step.group + ".h5:/" + set.name + "/";
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
    return x.str();
}

void FieldWriter::Impl::writeXdmf() {
    // The steps already described are kept as text, and each listing formats only its new steps'
    // (the bytes written still grow with the series).
    for (const std::size_t listed = steps.size() - (stepOpen ? 1 : 0); xdmfSteps < listed; ++xdmfSteps)
        xdmfBody += xdmfStep(steps[xdmfSteps]);
    // Write beside, then rename: a reader (or a crash) never sees a half-written file.
    const std::string temporary = xdmfPath + ".tmp";
    {
        std::ofstream out(temporary, std::ios::trunc);
        if (!out) throw Error(temporary + ": cannot open for writing");
        errno = 0;
        out << kXdmfHead << xdmfBody << kXdmfTail;
        out.flush();
        if (!out) {
            const std::string reason = errno ? std::string(": ") + std::strerror(errno) : std::string();
            out.close();
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw Error(temporary + ": cannot write" + reason + "; " + xdmfPath + " is left as it was");
        }
    }
    publishFile(temporary, xdmfPath, Durability::Deferred);
    unsynced = true;
}

bool FieldWriter::Impl::readStep(const std::string& group, double keepBefore, StepRecord& step) const {
    const std::string path = stepPath(group);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error) || H5Fis_hdf5(path.c_str()) <= 0) return false;
    Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file.valid() || H5Aexists(file.get(), "time") <= 0) return false;
    Hdf5Handle timeAttribute(H5Aopen(file.get(), "time", H5P_DEFAULT), H5Aclose);
    step = {0.0, group, {}};
    if (!timeAttribute.valid() || H5Aread(timeAttribute.get(), H5T_NATIVE_DOUBLE, &step.time) < 0) return false;
    if (!(step.time < keepBefore)) return false;

    // The sets and their fields, in the order writePointSet wrote them.
    auto linkNames = [](hid_t parent) {
        std::vector<std::string> names;
        auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
            static_cast<std::vector<std::string>*>(data)->push_back(name);
            return 0;
        };
        if (H5Literate(parent, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collect, &names) < 0) {
            names.clear();  // a file from before creation order was tracked: name order will do
            H5Literate(parent, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names);
        }
        return names;
    };
    for (const std::string& setName : linkNames(file.get())) {
        Hdf5Handle set(H5Gopen2(file.get(), setName.c_str(), H5P_DEFAULT), H5Gclose);
        if (!set.valid()) return false;
        SetRecord record{setName, 0, {}};
        for (const std::string& name : linkNames(set.get())) {
            Hdf5Handle dataset(H5Dopen2(set.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
            Hdf5Handle space(dataset.valid() ? H5Dget_space(dataset.get()) : -1, H5Sclose);
            hsize_t dims[2] = {0, 1};
            if (!space.valid() || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0) return false;
            if (name == "positions") record.count = static_cast<std::size_t>(dims[0]);
            if (name == "positions" || name == "connectivity") continue;
            std::string components;
            if (H5Aexists(dataset.get(), "components") > 0) {
                Hdf5Handle attribute(H5Aopen(dataset.get(), "components", H5P_DEFAULT), H5Aclose);
                Hdf5Handle type(attribute.valid() ? H5Aget_type(attribute.get()) : -1, H5Tclose);
                if (!type.valid()) return false;
                components.assign(H5Tget_size(type.get()), '\0');
                if (H5Aread(attribute.get(), type.get(), &components[0]) < 0) return false;
                components.resize(std::strlen(components.c_str()));
            }
            const int columns = static_cast<int>(dims[1]);
            record.attributes.push_back({name, storedKindOf(components, columns), columns});
        }
        step.sets.push_back(std::move(record));
    }
    return true;
}

FieldWriter::FieldWriter(const std::string& directory, int dimension, double keepStepsBefore)
    : impl_(std::make_unique<Impl>()) {
    QS_CHECK(dimension >= 1 && dimension <= 3,
             "FieldWriter: dimension must be 1, 2 or 3, got " << dimension);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // we report errors ourselves, as qs::Error
    const std::filesystem::path dir = std::filesystem::path(directory.empty() ? std::string(".") : directory);
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) throw Error(directory + ": cannot create output directory: " + error.message());

    Impl& s = *impl_;
    hdf5Path_ = (dir / kHdf5FileName).string();
    xdmfPath_ = (dir / kXdmfFileName).string();
    s.hdf5Path = hdf5Path_;
    s.xdmfPath = xdmfPath_;
    s.stepDirectory = dir / kStepDirectoryName;
    s.dimension = dimension;

    // Take over the steps already written before keepStepsBefore, in order, up to the first one
    // missing, unreadable or later; every other step file (and any temporary) is removed.
    std::filesystem::create_directories(s.stepDirectory, error);
    if (error) throw Error(s.stepDirectory.string() + ": cannot create directory: " + error.message());
    for (Impl::StepRecord step; s.readStep(stepGroupName(static_cast<int>(s.steps.size())), keepStepsBefore, step);)
        s.steps.push_back(std::move(step));
    // The new index first: a crash from here on finds fields.h5 naming only files that exist.
    s.publishListing();
    for (const auto& entry : std::filesystem::directory_iterator(s.stepDirectory, error)) {
        const std::string name = entry.path().filename().string();
        bool kept = false;
        for (const Impl::StepRecord& step : s.steps) kept = kept || name == step.group + ".h5";
        if (!kept && isStepFileName(name)) std::filesystem::remove(entry.path(), error);
    }
}

FieldWriter::~FieldWriter() {
    if (!impl_) return;
    // The steps ended and not yet listed are listed (an open step is not among them); a failure
    // here leaves them as the last listing had them, each step still in its own file.
    if (impl_->listingPending) {
        try {
            impl_->publishListing();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "quicksand: warning: the last outputs are in %s but not listed in %s: %s\n",
                         impl_->stepDirectory.string().c_str(), hdf5Path_.c_str(), e.what());
        }
    }
    // A step still open here was left by an exception part way through it: abandon it rather
    // than publish half a step. The series stays as after the last endStep().
    impl_->stepGroup.close();
    impl_->stepFile.close();
    std::error_code ignored;
    if (!impl_->stepTemporary.empty()) std::filesystem::remove(impl_->stepTemporary, ignored);
}

int FieldWriter::stepsWritten() const {
    return static_cast<int>(impl_->steps.size()) - (impl_->stepOpen ? 1 : 0);
}

void FieldWriter::beginStep(double time) {
    Impl& s = *impl_;
    QS_CHECK(!s.stepOpen, hdf5Path_ << ": beginStep(" << time << ") while the step at t = "
                                    << s.steps.back().time << " s is still open (call endStep first)");
    const std::string group = stepGroupName(static_cast<int>(s.steps.size()));
    s.stepTemporary = s.stepPath(group) + ".tmp";
    s.stepFile = Hdf5Handle(
        H5Fcreate(s.stepTemporary.c_str(), H5F_ACC_TRUNC, creationOrdered(H5P_FILE_CREATE).get(), H5P_DEFAULT),
        H5Fclose);
    if (!s.stepFile.valid())
        fail(s.stepTemporary, "create the file of the step at t = " + formatDouble(time) + " s");
    try {
        s.stepGroup = Hdf5Handle(H5Gopen2(s.stepFile.get(), "/", H5P_DEFAULT), H5Gclose);
        if (!s.stepGroup.valid()) fail(s.stepTemporary, "open group /");
        s.writeDimensionAttribute(s.stepFile.get(), s.stepTemporary);
        s.writeDoubleAttribute(s.stepGroup.get(), "/", "time", time);
    } catch (...) {
        s.stepGroup.close();
        s.stepFile.close();
        std::error_code ignored;
        std::filesystem::remove(s.stepTemporary, ignored);
        s.stepTemporary.clear();
        throw;
    }
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

    const std::string groupPath = "/" + setName;
    Hdf5Handle group(
        H5Gcreate2(s.stepGroup.get(), setName.c_str(), H5P_DEFAULT, creationOrdered(H5P_GROUP_CREATE).get(), H5P_DEFAULT),
        H5Gclose);
    if (!group.valid()) fail(s.stepTemporary, "create group " + groupPath);

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
    s.stepGroup.close();
    const bool closed = s.stepFile.close();
    try {
        if (!closed) fail(s.stepTemporary, "close file");
        publishFile(s.stepTemporary, s.stepPath(s.steps.back().group), Durability::Deferred);
        s.unsynced = true;
    } catch (...) {
        // The step is lost, the series before it is not: forget it and remove its remains.
        std::error_code ignored;
        std::filesystem::remove(s.stepTemporary, ignored);
        s.steps.pop_back();
        s.stepOpen = false;
        s.stepTemporary.clear();
        throw;
    }
    s.stepTemporary.clear();
    s.stepOpen = false;
    s.listingPending = true;
    listIfDue();
}

void FieldWriter::listIfDue(std::chrono::steady_clock::time_point now) {
    Impl& s = *impl_;
    if (s.listingPending && std::chrono::duration<double>(now - s.lastListing).count() >= s.listingInterval)
        s.publishListing();
}

void FieldWriter::setListingInterval(double seconds) { impl_->listingInterval = seconds; }

void FieldWriter::makeDurable() {
    Impl& s = *impl_;
    if (s.listingPending) s.publishListing();
    if (!s.unsynced) return;
    // One syncfs for the lot: an fsync per file commits the file system's journal once per file,
    // which for a run's 200 outputs cost as much as the fsyncs it replaced.
    syncFileSystem(std::filesystem::path(s.hdf5Path).parent_path().string());
    s.unsynced = false;
}

}  // namespace qs
