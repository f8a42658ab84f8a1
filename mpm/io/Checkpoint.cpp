#include "io/Checkpoint.hpp"

#include "core/Error.hpp"
#include "io/Hdf5File.hpp"

#include <hdf5.h>
#include <zlib.h>

#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <utility>
#include <vector>

namespace qs {

namespace {

const char* const kFormat = "quicksand-checkpoint";
// Version 2: sealed (a CRC-32 in the user block, see "The seal" below).
const int kVersion = 2;

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

namespace {

// The seal. HDF5 does not survive hostile files: the fuzzer (tests/fuzz) crashed HDF5 1.10 with
// a few changed bytes, inside H5Lvisit, and found it leaking what it had parsed of a garbled
// object header. So HDF5 never sees a checkpoint that is not byte for byte what quicksand wrote:
// the file begins with a user block (HDF5 skips it) holding a CRC-32 (zlib) of the rest,
//   "quicksand-checkpoint\nbytes N\ncrc32 XXXXXXXX\n", zero-padded to kSealBytes,
// which is checked before the file is handed to HDF5.
constexpr std::size_t kSealBytes = 512;  // HDF5's smallest user block
const char* const kSealMagic = "quicksand-checkpoint\n";

/// CRC-32 of the file's bytes after the seal, and how many there are.
std::pair<std::uint32_t, std::uintmax_t> payloadChecksum(std::ifstream& in, const std::string& path) {
    in.seekg(static_cast<std::streamoff>(kSealBytes));
    uLong crc = crc32(0L, Z_NULL, 0);
    std::uintmax_t bytes = 0;
    std::vector<char> buffer(1 << 16);
    while (in) {
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        const std::streamsize got = in.gcount();
        if (got <= 0) break;
        crc = crc32(crc, reinterpret_cast<const Bytef*>(buffer.data()), static_cast<uInt>(got));
        bytes += static_cast<std::uintmax_t>(got);
    }
    if (in.bad()) throw Error(path + ": cannot read checkpoint: read error");
    return {static_cast<std::uint32_t>(crc), bytes};
}

/// Writes the seal into the user block of the closed file at `path`.
void sealFile(const std::string& path) {
    std::uint32_t crc = 0;
    std::uintmax_t bytes = 0;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error(path + ": cannot reopen to seal the checkpoint");
        std::tie(crc, bytes) = payloadChecksum(in, path);
    }
    char seal[kSealBytes] = {};
    std::snprintf(seal, sizeof seal, "%sbytes %llu\ncrc32 %08x\n", kSealMagic,
                  static_cast<unsigned long long>(bytes), static_cast<unsigned>(crc));
    std::fstream out(path, std::ios::binary | std::ios::in | std::ios::out);
    out.write(seal, sizeof seal);
    out.flush();
    if (!out) throw Error(path + ": cannot write the checkpoint's seal");
}

/// Refuses, before HDF5 parses anything, a file that is not exactly what sealFile sealed.
void requireIntactSeal(const std::string& path) {
    static const char hdf5Signature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
    const std::string cannot = path + ": cannot read checkpoint: ";
    std::ifstream in(path, std::ios::binary);
    char seal[kSealBytes + 1] = {};  // one more: the text is always terminated
    in.read(seal, kSealBytes);
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    if (std::strncmp(seal, kSealMagic, std::strlen(kSealMagic)) != 0) {
        if (got >= sizeof hdf5Signature && std::memcmp(seal, hdf5Signature, sizeof hdf5Signature) == 0)
            throw Error(path + ": not a quicksand checkpoint: an HDF5 file without quicksand's seal (another "
                               "program's file, or a checkpoint of a quicksand older than checkpoint version " +
                        std::to_string(kVersion) + ")");
        throw Error(cannot + "not an HDF5 file");
    }
    if (got < kSealBytes)
        throw Error(cannot + "truncated: " + std::to_string(got) + " bytes, shorter than its " +
                    std::to_string(kSealBytes) + "-byte seal");
    // Every byte of the seal counts: it must be exactly what sealFile writes for the values it names.
    unsigned long long bytes = 0;
    unsigned crc = 0;
    const char* text = seal + std::strlen(kSealMagic);
    const char* const end = seal + kSealBytes;
    bool parsed = std::strncmp(text, "bytes ", 6) == 0;
    if (parsed) {
        const auto b = std::from_chars(text + 6, end, bytes);  // defined on overflow, unlike sscanf
        parsed = b.ec == std::errc() && end - b.ptr > 7 && std::strncmp(b.ptr, "\ncrc32 ", 7) == 0;
        if (parsed) parsed = std::from_chars(b.ptr + 7, end, crc, 16).ec == std::errc();
    }
    char expected[kSealBytes] = {};
    if (parsed) std::snprintf(expected, sizeof expected, "%sbytes %llu\ncrc32 %08x\n", kSealMagic, bytes, crc);
    if (!parsed || std::memcmp(seal, expected, kSealBytes) != 0)
        throw Error(cannot + "its seal (the first " + std::to_string(kSealBytes) + " bytes) is damaged");
    in.clear();
    const auto [actualCrc, actualBytes] = payloadChecksum(in, path);
    if (actualBytes != bytes)
        throw Error(cannot + "truncated or extended: " + std::to_string(actualBytes) + " bytes after the seal, " +
                    std::to_string(bytes) + " written");
    if (actualCrc != crc) throw Error(cannot + "damaged: its CRC-32 does not match the one written with it");
}

}  // namespace

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
            Hdf5Handle creation(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
            if (!creation.valid() || H5Pset_userblock(creation.get(), kSealBytes) < 0)
                fail(temporary, "reserve the seal's user block");
            Hdf5Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, creation.get(), H5P_DEFAULT), H5Fclose);
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
        sealFile(temporary);
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
    requireIntactSeal(path);
    const std::uintmax_t fileSize = std::filesystem::file_size(path, error);
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
        // the entries are stored contiguously and uncompressed: none can hold more than the file
        if (static_cast<std::uintmax_t>(count) > fileSize / sizeof(double))
            throw Error(path + ": cannot read checkpoint: entry '" + name + "' claims " + std::to_string(count) +
                        " values, more than the file's " + std::to_string(fileSize) + " bytes hold");

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
