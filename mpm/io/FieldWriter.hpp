#pragma once
// FieldWriter: material-point fields over time, in OUTDIR/fields.h5 with OUTDIR/fields.xdmf beside
// it so that ParaView (or VisIt) opens the whole series as one time-dependent data set.
//
// Never half-written: each output step is a file of its own, OUTDIR/fields/step_NNNNNN.h5,
// written under a temporary name and renamed into place. fields.h5 itself holds only external
// links, /step_NNNNNN -> fields/step_NNNNNN.h5:/, and is replaced (by rename) when it lists new
// steps, as is fields.xdmf: after each step, or at most once per listing interval. A crash or a
// full disk mid-step loses that step only. The files reach the disk (against a power loss) at
// makeDurable(), which the run calls before each checkpoint.
//
// Usage:
//   FieldWriter writer(outputDirectory, D);          // a new series: both files, no steps
//   for each output time t:
//     writer.beginStep(t);
//     writer.writePointSet("solid", n, positions, {{"porosity", phi, 1},
//                                                  {"effective_stress", sigma, 6}});
//     writer.writePointSet("liquid", m, ...);
//     writer.endStep();                              // the step's file, listed in fields.xdmf
//
// Layout of fields.h5 as a reader sees it through the links (all datasets double, row-major,
// one row per point):
//   /                       attribute dimension (int, 1..3)
//   /step_000000            attribute time (double, s); also dimension (it is a file's root)
//   /step_000000/solid/positions     [n][3]  m, always XYZ (see "Vertical axis" below)
//   /step_000000/solid/connectivity  [n]     int32 0..n-1: the explicit Polyvertex topology, as
//                                            ParaView's Xdmf3 reader reads point ids from it
//   /step_000000/solid/<field>       [n] scalar, [n][3] vector, [n][6] symmetric tensor,
//                                    [n][k] anything else (XDMF "Matrix")
//
// Vertical axis: the last grid coordinate is vertical (core/Types.hpp). So that ParaView shows
// an upright column, positions and vectors are padded to 3D with the vertical axis kept in Z:
//   1D (z) -> (0, 0, z);   2D (x, z) -> (x, 0, z);   3D unchanged.
// Symmetric tensors are already full 3D (materials work in 3D whatever D is) and are written
// unchanged in the caller's Voigt order xx, yy, zz, yz, xz, xy (the dataset's attribute
// "components" says so); zz (index 2) is the vertical normal component.
//
// fields.xdmf (XDMF 3): one temporal collection; per step a spatial collection with one
// Polyvertex grid per non-empty point set. An empty point set still gets its (empty) datasets in
// fields.h5 but no XDMF grid, because readers reject zero-sized DataItems.
//
// Errors: any HDF5 or file failure throws qs::Error naming the file and the operation.
// Not thread-safe; call from one thread (HDF5 serial is not thread-safe either).
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace qs {

/// How a field's components are meant, when the component count alone cannot say (1D vectors).
enum class FieldKind {
    Automatic,        ///< 1 -> Scalar, 6 -> SymmetricTensor, dimension (2, 3) -> Vector, else Matrix
    Scalar,           ///< 1 component
    Vector,           ///< `dimension` components, padded to 3 like positions
    SymmetricTensor,  ///< 6 components, Voigt order xx, yy, zz, yz, xz, xy (3D components)
};

/// One field of a point set, borrowed for the duration of writePointSet().
struct PointField {
    std::string name;    ///< dataset name: letters, digits, '_', '-', '.'
    const double* data;  ///< data[count * components], row-major per point; integers as double
    int components;
    FieldKind kind = FieldKind::Automatic;  ///< set Vector for a 1D vector (1 component)
};

class FieldWriter {
public:
    /// Creates directory if needed, then writes directory/fields.h5 and directory/fields.xdmf.
    /// The steps already in directory/fields with a time before keepStepsBefore (s) are kept, in
    /// order (a resumed run passes its first new output time); all other step files are removed.
    /// The default keeps none: a new series. dimension = 1..3.
    explicit FieldWriter(const std::string& directory, int dimension, double keepStepsBefore = -1e300);
    /// Abandons a step still open (left by an exception): its temporary is removed, the series
    /// stays as after the last endStep().
    ~FieldWriter();

    FieldWriter(const FieldWriter&) = delete;
    FieldWriter& operator=(const FieldWriter&) = delete;

    /// Starts output time `time` (s). Pre: no step open. Times should increase (not checked:
    /// ParaView sorts them).
    void beginStep(double time);
    /// Writes one point set into the open step. positions: count * dimension doubles (m).
    /// Pre: a step is open; setName not yet written in this step. Data is copied: the caller's
    /// arrays may change after the call.
    void writePointSet(const std::string& setName, std::size_t count, const double* positions,
                       const std::vector<PointField>& fields);
    /// Publishes the step's file, then lists it in fields.h5 and fields.xdmf (each by rename),
    /// or leaves the listing for later within the listing interval. If publishing the step's file
    /// fails, the step is dropped and the files are as after the previous step; if only the index
    /// or the XDMF fails, the step's file is in place but not yet listed (the next listing lists
    /// it). Pre: a step is open.
    void endStep();

    /// Lists new steps in fields.h5 and fields.xdmf at most once per `seconds` of wall time; 0,
    /// the default, lists each step as it ends. Each listing replaces both files, and a run whose
    /// outputs come many to the second (a 1D column) spent more on them than on the step files.
    void setListingInterval(double seconds);
    /// Lists the steps ended and not yet listed if the interval has passed since the last
    /// listing; cheap when none waits. The run calls it every step, so that a step is listed
    /// within the interval, whenever the next output comes; makeDurable() and the destructor
    /// list what is left. `now`: the caller's reading of the clock, which it has at hand.
    void listIfDue(std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());

    /// Lists the steps not yet listed, then forces every file published since the last call
    /// (the step files, fields.h5, fields.xdmf) and their renames to disk, by one syncfs of their
    /// file system. Without it a published file is whole against a crash of the program, not of
    /// the machine; the run calls it before each checkpoint, so that after a power loss a
    /// checkpoint never outlives the outputs before it. Throws qs::Error naming the output
    /// directory and the system's reason if the flush fails.
    void makeDurable();

    const std::string& hdf5Path() const { return hdf5Path_; }
    const std::string& xdmfPath() const { return xdmfPath_; }
    int stepsWritten() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string hdf5Path_;
    std::string xdmfPath_;
};

}  // namespace qs
