// A thin RAII layer over the HDF5 C API: files, groups, 1-D/2-D datasets of doubles, integers
// and strings, pre-sized tables written row by row, and attributes; failures become exceptions.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rotorsweep::io {

/// An owned HDF5 identifier (file, group, dataset, ...), closed with the matching H5?close.
class Hdf5Handle {
 public:
  Hdf5Handle() = default;
  Hdf5Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  ~Hdf5Handle();
  hid_t id() const { return id_; }
  /// Gives up ownership: the caller closes the identifier.
  hid_t release() {
    const hid_t id = id_;
    id_ = -1;
    return id;
  }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

/// The element type of a pre-sized table column (Hdf5Location::create_column).
enum class ColumnType { float64, int64, flag, text };

/// A column of a table: `rows` elements, or rows × `width` when width > 0, or rows × width ×
/// `depth` when depth > 0 too; text columns hold fixed-length UTF-8 strings of at most text_length bytes.
struct ColumnShape {
  hsize_t rows = 0;
  hsize_t width = 0;
  std::size_t text_length = 0;
  hsize_t depth = 0;
};

/// A file or group to write into or read from.
class Hdf5Location {
 public:
  /// Creates (truncating) the file at path.
  static Hdf5Location create_file(const std::string& path);
  /// Opens an existing file read-only.
  static Hdf5Location open_file(const std::string& path);
  /// Opens an existing file to write into it.
  static Hdf5Location open_file_for_writing(const std::string& path);
  /// Creates a file that lives in memory only (HDF5's core driver, no backing store); `name`
  /// names it in messages, and file_image() hands out its bytes.
  static Hdf5Location create_in_memory(const std::string& name);

  Hdf5Location create_group(const std::string& name) const;
  Hdf5Location open_group(const std::string& name) const;
  bool has(const std::string& name) const;
  /// Names of the links (datasets, groups) directly in this location, sorted.
  std::vector<std::string> members() const;
  void flush() const;
  /// Closes a file, reporting a failure to write its last buffers (the destructor cannot).
  void close();
  /// The bytes of the whole file as it would be on disk (flushes first); readable by any HDF5
  /// reader, e.g. h5py.File(io.BytesIO(image)).
  std::vector<unsigned char> file_image() const;

  /// dims empty: one dimension of data.size(). Numeric datasets get units "1" (set_units changes them).
  void write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> dims = {},
             const std::string& description = "") const;
  void write(const std::string& name, const std::vector<std::int64_t>& data,
             const std::string& description = "") const;
  void write(const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> dims,
             const std::string& description) const;
  void write(const std::string& name, const std::vector<std::string>& data,
             const std::string& description = "") const;

  /// A dataset whose file space is allocated at creation and never changes (contiguous, no
  /// fill written): writing its rows later changes raw data only, never the file's metadata.
  /// Numeric columns carry `units` (UDUNITS spelling, "1" for dimensionless).
  void create_column(const std::string& name, ColumnType type, const ColumnShape& shape,
                     const std::string& description, const std::string& units = "1") const;
  /// Rows `rows` (ascending, distinct) of a column, from consecutive rows in memory.
  void write_rows(const std::string& name, const std::vector<hsize_t>& rows, const double* data) const;
  void write_rows(const std::string& name, const std::vector<hsize_t>& rows, const std::int64_t* data) const;
  /// Flags as 0 / 1.
  void write_rows(const std::string& name, const std::vector<hsize_t>& rows, const signed char* data) const;
  void write_rows(const std::string& name, const std::vector<hsize_t>& rows,
                  const std::vector<std::string>& data) const;
  /// Text rows already padded with NUL to `length` bytes each, the column's length.
  void write_rows(const std::string& name, const std::vector<hsize_t>& rows, const char* text,
                  std::size_t length) const;
  /// Rows [first, first + count) of a column (any number of values per row).
  std::vector<double> read_rows_doubles(const std::string& name, hsize_t first, hsize_t count) const;
  std::vector<std::int64_t> read_rows_integers(const std::string& name, hsize_t first, hsize_t count) const;
  std::vector<std::string> read_rows_strings(const std::string& name, hsize_t first, hsize_t count) const;
  /// A flag column as 0 / 1.
  std::vector<signed char> read_flags(const std::string& name) const;
  /// "" when dataset `name` is what create_column(name, type, shape, …) makes (its dimensions and
  /// element type), else what differs ("is missing", "has shape (32, 5) where its scene gives (32, 51)").
  std::string column_mismatch(const std::string& name, ColumnType type, const ColumnShape& shape) const;
  /// The number of rows and the values per row (1 for a 1-D dataset).
  std::pair<hsize_t, hsize_t> shape(const std::string& name) const;

  std::vector<double> read_doubles(const std::string& name, std::vector<hsize_t>* dims = nullptr) const;
  std::vector<std::int64_t> read_integers(const std::string& name) const;
  std::vector<std::string> read_strings(const std::string& name) const;
  /// The raw bytes of a dataset in its file type (for byte-for-byte comparisons).
  std::vector<unsigned char> read_bytes(const std::string& name) const;

  /// The units attribute of numeric dataset `name` (UDUNITS spelling, e.g. "m", "N", "rad").
  void set_units(const std::string& name, const std::string& units) const;

  void set_attribute(const std::string& name, double value) const;
  void set_attribute(const std::string& name, std::int64_t value) const;
  void set_attribute(const std::string& name, const std::string& value) const;
  /// A boolean in h5py's convention (int8 enum FALSE = 0, TRUE = 1), read back as numpy.bool_.
  void set_flag(const std::string& name, bool value) const;

  /// Removes an attribute if it is there.
  void remove_attribute(const std::string& name) const;
  bool has_attribute(const std::string& name) const;
  double attribute_double(const std::string& name) const;
  std::string attribute_string(const std::string& name) const;
  bool attribute_flag(const std::string& name) const;

  hid_t id() const { return handle_.id(); }
  /// The file's path (its name, for a file in memory).
  const std::string& path() const { return path_; }

 private:
  Hdf5Location(Hdf5Handle handle, std::string path) : handle_(std::move(handle)), path_(std::move(path)) {}
  [[noreturn]] void fail(const std::string& what, const std::string& name) const;
  void write_dataset(const std::string& name, hid_t file_type, hid_t memory_type,
                     const std::vector<hsize_t>& dims, const void* data,
                     const std::string& description) const;
  Hdf5Handle open_dataset(const std::string& name) const;
  template <class T>
  std::vector<T> read_numbers(const std::string& name, hid_t memory_type, std::vector<hsize_t>* dims) const;
  void write_selected_rows(const std::string& name, const std::vector<hsize_t>& rows, hid_t memory_type,
                           const void* data) const;
  /// Rows `rows` (ascending) of dataset `set` written as their whole span: the span read, the rows laid
  /// over it, written back in one piece.
  void write_span(hid_t set, hid_t file_space, int rank, const hsize_t dims[3],
                  const std::vector<hsize_t>& rows, hid_t memory_type, std::size_t row_bytes,
                  const void* data, const std::string& name) const;
  /// Closes a dataset just written; a failure to write its buffered rows there throws.
  void close_written(Hdf5Handle set, const std::string& name) const;
  void read_selected_rows(const std::string& name, hsize_t first, hsize_t count, hid_t memory_type,
                          void* data) const;

  Hdf5Handle handle_;
  std::string path_;
};

}  // namespace rotorsweep::io
