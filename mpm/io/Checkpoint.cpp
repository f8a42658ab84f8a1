#include "io/Checkpoint.hpp"

#include "core/Error.hpp"
#include "io/Hdf5File.hpp"

#include <hdf5.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

namespace qs {

namespace {

const char* const kFormat = "quicksand-checkpoint";
const int kVersion = 1;

/// Checkpoint errors name the file they concern.
[[noreturn]] void fail(const std::string& file, const std::string& operation) { failHdf5(file, operation); }

const char* kindName(std::size_t variantIndex) {
    static const char* const names[] = {"doubles", "integers", "a scalar"};
    return names[variantIndex];
}

// ---- writing ---------------------------------------------------------------------------------

void writeRootAttributes(hid_t file, const std::string& path) {
    Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    Hdf5Handle stringType(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!space.valid() || !stringType.valid() || H5Tset_size(stringType.get(), std::strlen(kFormat) + 1) < 0)
        fail(path, "make the root attributes");
    Hdf5Handle format(H5Acreate2(file, "format", stringType.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      H5Aclose);
    if (!format.valid() || H5Awrite(format.get(), stringType.get(), kFormat) < 0)
        fail(path, "write attribute /@format");
    Hdf5Handle version(H5Acreate2(file, "version", H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                       H5Aclose);
    if (!version.valid() || H5Awrite(version.get(), H5T_NATIVE_INT, &kVersion) < 0)
        fail(path, "write attribute /@version");
}

/// One dataset: rank 1 of `size` elements, or a scalar dataspace when `scalar`.
void writeEntry(hid_t file, const std::string& path, const std::string& name, const void* data,
                std::size_t size, bool scalar, hid_t memoryType, hid_t fileType) {
    const hsize_t dims[1] = {static_cast<hsize_t>(size)};
    Hdf5Handle space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, nullptr), H5Sclose);
    // Names with '/' live in groups: let HDF5 make the groups on the way.
    Hdf5Handle linkProperties(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (!space.valid() || !linkProperties.valid() ||
        H5Pset_create_intermediate_group(linkProperties.get(), 1) < 0)
        fail(path, "prepare dataset '" + name + "'");
    Hdf5Handle dataset(
        H5Dcreate2(file, name.c_str(), fileType, space.get(), linkProperties.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose);
    if (!dataset.valid()) fail(path, "create dataset '" + name + "'");
    // A zero-sized dataset needs no write (and HDF5 may reject the null buffer of an empty vector).
    if ((scalar || size > 0) && H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail(path, "write dataset '" + name + "'");
}

// ---- reading ---------------------------------------------------------------------------------

/// Collects the names of all links under the root; types are checked afterwards, outside the C
/// callback, where throwing is safe.
herr_t collectLinkName(hid_t, const char* name, const H5L_info_t* info, void* data) {
    if (info->type == H5L_TYPE_HARD) static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
}

void readFormat(hid_t file, const std::string& path) {
    const std::string notOurs = path + ": not a quicksand checkpoint (no root attribute format = \"" +
                                kFormat + "\")";
    if (H5Aexists(file, "format") <= 0) throw Error(notOurs);
    Hdf5Handle attribute(H5Aopen(file, "format", H5P_DEFAULT), H5Aclose);
    Hdf5Handle type(attribute.valid() ? H5Aget_type(attribute.get()) : -1, H5Tclose);
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) != 0)
        throw Error(notOurs);
    std::string value(H5Tget_size(type.get()), '\0');
    if (H5Aread(attribute.get(), type.get(), &value[0]) < 0) fail(path, "read attribute /@format");
    value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
    if (value != kFormat) throw Error(notOurs);

    int version = 0;
    if (H5Aexists(file, "version") <= 0) throw Error(path + ": checkpoint has no version attribute");
    Hdf5Handle versionAttribute(H5Aopen(file, "version", H5P_DEFAULT), H5Aclose);
    if (!versionAttribute.valid() || H5Aread(versionAttribute.get(), H5T_NATIVE_INT, &version) < 0)
        fail(path, "read attribute /@version");
    if (version != kVersion)
        throw Error(path + ": checkpoint version " + std::to_string(version) + ", this quicksand reads version " +
                    std::to_string(kVersion));
}

}  // namespace

// ---- CheckpointData --------------------------------------------------------------------------

void CheckpointData::checkName(const std::string& name) {
    QS_CHECK(!name.empty() && name.front() != '/' && name.back() != '/' &&
                 name.find("//") == std::string::npos,
             "checkpoint entry name '" << name << "' must be non-empty, without leading, trailing or double '/'");
}

void CheckpointData::put(const std::string& name, std::vector<double> values) {
    checkName(name);
    entries_[name] = std::move(values);
}

void CheckpointData::put(const std::string& name, std::vector<std::int64_t> values) {
    checkName(name);
    entries_[name] = std::move(values);
}

void CheckpointData::putScalar(const std::string& name, double v) {
    checkName(name);
    entries_[name] = v;
}

const CheckpointData::Entry& CheckpointData::entry(const std::string& name, const char* wanted) const {
    const auto it = entries_.find(name);
    QS_CHECK(it != entries_.end(), "checkpoint has no entry '" << name << "' (" << wanted << " expected)");
    return it->second;
}

const std::vector<double>& CheckpointData::doubles(const std::string& name) const {
    const Entry& e = entry(name, "doubles");
    QS_CHECK(e.index() == 0, "checkpoint entry '" << name << "' holds " << kindName(e.index())
                                                  << ", not doubles");
    return std::get<0>(e);
}

const std::vector<std::int64_t>& CheckpointData::integers(const std::string& name) const {
    const Entry& e = entry(name, "integers");
    QS_CHECK(e.index() == 1, "checkpoint entry '" << name << "' holds " << kindName(e.index())
                                                  << ", not integers");
    return std::get<1>(e);
}

double CheckpointData::scalar(const std::string& name) const {
    const Entry& e = entry(name, "a scalar");
    QS_CHECK(e.index() == 2, "checkpoint entry '" << name << "' holds " << kindName(e.index())
                                                  << ", not a scalar");
    return std::get<2>(e);
}

bool CheckpointData::has(const std::string& name) const { return entries_.count(name) > 0; }

std::vector<std::string> CheckpointData::names() const {
    std::vector<std::string> result;
    result.reserve(entries_.size());
    for (const auto& entry : entries_) result.push_back(entry.first);
    return result;
}

// ---- files -----------------------------------------------------------------------------------

void writeCheckpoint(const std::string& path, const CheckpointData& data) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // we report errors ourselves, as qs::Error
    // An entry "a" and an entry "a/b" cannot both exist: "a" would be a dataset and a group.
    for (const auto& entry : data.entries_)
        for (std::size_t slash = entry.first.find('/'); slash != std::string::npos;
             slash = entry.first.find('/', slash + 1))
            QS_CHECK(!data.has(entry.first.substr(0, slash)),
                     path << ": checkpoint entries '" << entry.first.substr(0, slash) << "' and '" << entry.first
                          << "' clash (one would be inside the other)");

    const std::string temporary = path + ".tmp";
    try {
        {
            Hdf5Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
            if (!file.valid()) fail(temporary, "create file");
            writeRootAttributes(file.get(), temporary);
            for (const auto& [name, entry] : data.entries_) {
                if (const auto* d = std::get_if<std::vector<double>>(&entry))
                    writeEntry(file.get(), temporary, name, d->data(), d->size(), false, H5T_NATIVE_DOUBLE,
                               H5T_IEEE_F64LE);
                else if (const auto* i = std::get_if<std::vector<std::int64_t>>(&entry))
                    writeEntry(file.get(), temporary, name, i->data(), i->size(), false, H5T_NATIVE_INT64,
                               H5T_STD_I64LE);
                else
                    writeEntry(file.get(), temporary, name, &std::get<double>(entry), 1, true, H5T_NATIVE_DOUBLE,
                               H5T_IEEE_F64LE);
            }
            if (!file.close()) fail(temporary, "close file");
        }
        publishFile(temporary, path);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

CheckpointData readCheckpoint(const std::string& path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // we report errors ourselves, as qs::Error
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw Error(path + ": cannot read checkpoint: no such file");
    if (H5Fis_hdf5(path.c_str()) <= 0) throw Error(path + ": cannot read checkpoint: not an HDF5 file");
    Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file.valid()) fail(path, "open checkpoint");
    readFormat(file.get(), path);

    std::vector<std::string> links;
    if (H5Lvisit(file.get(), H5_INDEX_NAME, H5_ITER_INC, collectLinkName, &links) < 0)
        fail(path, "list the checkpoint entries");

    CheckpointData data;
    for (const std::string& name : links) {
        Hdf5Handle object(H5Oopen(file.get(), name.c_str(), H5P_DEFAULT), H5Oclose);
        if (!object.valid()) fail(path, "open '" + name + "'");
        if (H5Iget_type(object.get()) != H5I_DATASET) continue;  // a group made by a '/' in a name
        const hid_t dataset = object.get();
        Hdf5Handle space(H5Dget_space(dataset), H5Sclose);
        Hdf5Handle type(H5Dget_type(dataset), H5Tclose);
        if (!space.valid() || !type.valid()) fail(path, "inspect dataset '" + name + "'");
        const H5S_class_t shape = H5Sget_simple_extent_type(space.get());
        const H5T_class_t typeClass = H5Tget_class(type.get());
        const hssize_t count = H5Sget_simple_extent_npoints(space.get());
        if (count < 0) fail(path, "size dataset '" + name + "'");

        if (shape == H5S_SCALAR && typeClass == H5T_FLOAT) {
            double value = 0.0;
            if (H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
                fail(path, "read scalar '" + name + "'");
            data.putScalar(name, value);
        } else if (shape == H5S_SIMPLE && typeClass == H5T_FLOAT) {
            std::vector<double> values(static_cast<std::size_t>(count));
            if (count > 0 && H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
                fail(path, "read doubles '" + name + "'");
            data.put(name, std::move(values));
        } else if (shape == H5S_SIMPLE && typeClass == H5T_INTEGER) {
            std::vector<std::int64_t> values(static_cast<std::size_t>(count));
            if (count > 0 && H5Dread(dataset, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
                fail(path, "read integers '" + name + "'");
            data.put(name, std::move(values));
        } else if (shape == H5S_NULL && (typeClass == H5T_FLOAT || typeClass == H5T_INTEGER)) {
            // Some writers store empty arrays with a null dataspace.
            if (typeClass == H5T_FLOAT) data.put(name, std::vector<double>{});
            else data.put(name, std::vector<std::int64_t>{});
        } else {
            throw Error(path + ": checkpoint entry '" + name +
                        "' is neither doubles, integers nor a scalar double");
        }
    }
    return data;
}

}  // namespace qs
