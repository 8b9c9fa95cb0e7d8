// The HDF5 C API behind Hdf5Location: creation properties without timestamps (so that the
// same results give the same bytes), UTF-8 strings, h5py-style booleans, row-wise table I/O.
#include "io/hdf5_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <stdexcept>

namespace rotorsweep::io {

namespace {

/// Before the library's first use: no error stack printed (every failure becomes an exception), and
/// no library shutdown at exit. HDF5 1.10 crashes in that shutdown on a file whose last write
/// failed (a full disk); our handles close every file themselves, so there is nothing left to do.
void prepare_hdf5() {
  static const bool prepared = [] { return H5dont_atexit() >= 0; }();
  // a thread-safe HDF5 keeps the error printing per thread: silence it in every thread that calls in
  thread_local const bool silenced = H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0;
  (void)prepared;
  (void)silenced;
}

/// The innermost entry of HDF5's error stack, or the OS reason it carries ("File too large"),
/// as ": <text>"; "" when the stack is empty.
std::string innermost_error() {
  std::string text;
  // no exception may cross HDF5's C frames (it would leave the library's lock and state behind): an
  // allocation that fails here stops the walk
  const auto first = [](unsigned n, const H5E_error2_t* error, void* out) noexcept -> herr_t {
    try {
      if (n == 0 && error->desc) *static_cast<std::string*>(out) = error->desc;
      return 0;
    } catch (...) {
      return -1;
    }
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, first, &text);
  // an OS failure carries "..., errno = 28, error message = 'No space left on device', ...": keep that
  const std::string marker = "error message = '";
  if (const auto at = text.find(marker); at != std::string::npos) {
    const auto begin = at + marker.size();
    text = text.substr(begin, text.find('\'', begin) - begin);
  }
  return text.empty() ? "" : ": " + text;
}

/// Throws the OS reason where the file at `path` cannot be accessed as `mode` (R_OK, W_OK) asks (a
/// permission, a directory on the way), else `otherwise` (the file is no HDF5 file).
[[noreturn]] void unopenable(const std::string& path, int mode, const std::string& otherwise) {
  if (::access(path.c_str(), mode) != 0)
    throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
  throw std::runtime_error(otherwise);
}

Hdf5Handle string_type() {
  Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.id(), H5T_VARIABLE);
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  return type;
}

/// Fixed-length UTF-8 strings of `length` bytes, padded with NUL (h5py reads them as bytes "S<length>").
Hdf5Handle text_type(std::size_t length) {
  Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.id(), std::max<std::size_t>(length, 1));
  H5Tset_strpad(type.id(), H5T_STR_NULLPAD);
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  return type;
}

Hdf5Handle flag_type() {
  Hdf5Handle type(H5Tenum_create(H5T_NATIVE_INT8), H5Tclose);
  const signed char no = 0, yes = 1;
  H5Tenum_insert(type.id(), "FALSE", &no);
  H5Tenum_insert(type.id(), "TRUE", &yes);
  return type;
}

/// Object creation properties without modification times.
Hdf5Handle untimed(hid_t list_class) {
  Hdf5Handle plist(H5Pcreate(list_class), H5Pclose);
  H5Pset_obj_track_times(plist.id(), false);
  return plist;
}

Hdf5Handle scalar_space() { return Hdf5Handle(H5Screate(H5S_SCALAR), H5Sclose); }

/// The attribute `name` of type `type`: the existing one when it has that type (so that writing it
/// again changes bytes in place and allocates nothing), a new one otherwise.
Hdf5Handle fresh_attribute(hid_t loc, const std::string& name, hid_t type) {
  if (H5Aexists(loc, name.c_str()) > 0) {
    Hdf5Handle existing(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
    const Hdf5Handle existing_type(H5Aget_type(existing.id()), H5Tclose);
    if (H5Tget_class(type) != H5T_STRING && H5Tequal(existing_type.id(), type) > 0) return existing;
    existing = Hdf5Handle();
    H5Adelete(loc, name.c_str());
  }
  const auto space = scalar_space();
  return Hdf5Handle(H5Acreate2(loc, name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
}

herr_t write_string_attribute(hid_t loc, const std::string& name, const std::string& value) {
  const auto type = string_type();
  const auto attribute = fresh_attribute(loc, name, type.id());
  const char* pointer = value.c_str();
  return attribute.id() < 0 ? -1 : H5Awrite(attribute.id(), type.id(), &pointer);
}

/// The "description" attribute every dataset carries (its meaning).
void describe(hid_t object, const std::string& description) {
  write_string_attribute(object, "description", description);
}

/// The "units" attribute of a numeric dataset (UDUNITS spelling, "1" for dimensionless); strings and
/// flags have none.
void give_units(hid_t set, const std::string& units) {
  const Hdf5Handle type(H5Dget_type(set), H5Tclose);
  const H5T_class_t kind = H5Tget_class(type.id());
  if (kind == H5T_INTEGER || kind == H5T_FLOAT) write_string_attribute(set, "units", units);
}

}  // namespace

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
  if (this != &other) {
    if (id_ >= 0 && close_) close_(id_);
    id_ = other.id_;
    close_ = other.close_;
    other.id_ = -1;
  }
  return *this;
}

Hdf5Handle::~Hdf5Handle() {
  if (id_ >= 0 && close_) close_(id_);
}

void Hdf5Location::fail(const std::string& what, const std::string& name) const {
  throw std::runtime_error("HDF5: cannot " + what + " '" + name + "' in " + path_ + innermost_error());
}

Hdf5Location Hdf5Location::create_file(const std::string& path) {
  prepare_hdf5();
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw std::runtime_error("cannot create output file '" + path + "'" + innermost_error());
  return Hdf5Location(Hdf5Handle(id, H5Fclose), path);
}

Hdf5Location Hdf5Location::open_file(const std::string& path) {
  prepare_hdf5();
  hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) {
    // a partial file its run still writes holds HDF5's file lock: read it without (the writer changes only
    // bytes in place and marks a row done after it is on disk; OutputTarget's locks keep writers apart)
    const Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    H5Pset_file_locking(access.id(), false, true);
    id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.id());
  }
  if (id < 0 && !std::filesystem::exists(path)) throw std::runtime_error("'" + path + "' does not exist");
  if (id < 0) unopenable(path, R_OK, "cannot open '" + path + "' as an HDF5 file");
  return Hdf5Location(Hdf5Handle(id, H5Fclose), path);
}

Hdf5Location Hdf5Location::open_file_for_writing(const std::string& path) {
  prepare_hdf5();
  // without HDF5's file lock: a reader holding the file open (`info`, h5py) must not make a run fail as it
  // reopens the file it has just created; OutputTarget's locks keep writers apart
  const Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_file_locking(access.id(), false, true);
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDWR, access.id());
  if (id < 0) unopenable(path, R_OK | W_OK, "cannot open '" + path + "' for writing" + innermost_error());
  return Hdf5Location(Hdf5Handle(id, H5Fclose), path);
}

Hdf5Location Hdf5Location::create_in_memory(const std::string& name) {
  prepare_hdf5();
  const Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (H5Pset_fapl_core(access.id(), 1 << 20, false) < 0)
    throw std::runtime_error("HDF5: cannot set up an in-memory file" + innermost_error());
  const hid_t id = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id());
  if (id < 0)
    throw std::runtime_error("HDF5: cannot create the in-memory file '" + name + "'" + innermost_error());
  return Hdf5Location(Hdf5Handle(id, H5Fclose), name);
}

Hdf5Location Hdf5Location::create_group(const std::string& name) const {
  const auto gcpl = untimed(H5P_GROUP_CREATE);
  const hid_t id = H5Gcreate2(this->id(), name.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT);
  if (id < 0) fail("create group", name);
  return Hdf5Location(Hdf5Handle(id, H5Gclose), path_);
}

Hdf5Location Hdf5Location::open_group(const std::string& name) const {
  const hid_t id = H5Gopen2(this->id(), name.c_str(), H5P_DEFAULT);
  if (id < 0) fail("open group", name);
  return Hdf5Location(Hdf5Handle(id, H5Gclose), path_);
}

bool Hdf5Location::has(const std::string& name) const {
  return H5Lexists(id(), name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> Hdf5Location::members() const {
  struct Collected {
    std::vector<std::string> names;
    std::exception_ptr failure;
  } collected;
  // no exception may cross HDF5's C frames (it would leave the library's lock and state behind): one
  // thrown here (an allocation that fails) stops the iteration and is thrown again after it
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) noexcept -> herr_t {
    auto& into = *static_cast<Collected*>(out);
    try {
      into.names.push_back(name);
      return 0;
    } catch (...) {
      into.failure = std::current_exception();
      return -1;
    }
  };
  H5Literate(id(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &collected);
  if (collected.failure) std::rethrow_exception(collected.failure);
  std::sort(collected.names.begin(), collected.names.end());
  return std::move(collected.names);
}

void Hdf5Location::flush() const {
  prepare_hdf5();
  if (H5Fflush(id(), H5F_SCOPE_GLOBAL) < 0) fail("flush", path_);
}

void Hdf5Location::close() {
  const hid_t id = handle_.release();
  if (id >= 0 && H5Fclose(id) < 0) fail("close", path_);
}

std::vector<unsigned char> Hdf5Location::file_image() const {
  flush();
  const ssize_t size = H5Fget_file_image(id(), nullptr, 0);
  if (size < 0) fail("take the image of", path_);
  std::vector<unsigned char> image(std::size_t(size), 0);
  if (H5Fget_file_image(id(), image.data(), image.size()) != size) fail("take the image of", path_);
  return image;
}

void Hdf5Location::write_dataset(const std::string& name, hid_t file_type, hid_t memory_type,
                                 const std::vector<hsize_t>& dims, const void* data,
                                 const std::string& description) const {
  const Hdf5Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
  const auto dcpl = untimed(H5P_DATASET_CREATE);
  const Hdf5Handle set(
      H5Dcreate2(id(), name.c_str(), file_type, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT), H5Dclose);
  if (set.id() < 0 || H5Dwrite(set.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("write dataset", name);
  if (!description.empty()) describe(set.id(), description);
  give_units(set.id(), "1");
}

void Hdf5Location::set_units(const std::string& name, const std::string& units) const {
  const auto set = open_dataset(name);
  give_units(set.id(), units);
}

void Hdf5Location::write(const std::string& name, const std::vector<double>& data, std::vector<hsize_t> dims,
                         const std::string& description) const {
  if (dims.empty()) dims = {hsize_t(data.size())};
  write_dataset(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data.data(), description);
}

void Hdf5Location::write(const std::string& name, const std::vector<std::int64_t>& data,
                         const std::string& description) const {
  write(name, data, {hsize_t(data.size())}, description);
}

void Hdf5Location::write(const std::string& name, const std::vector<std::int64_t>& data,
                         std::vector<hsize_t> dims, const std::string& description) const {
  write_dataset(name, H5T_STD_I64LE, H5T_NATIVE_INT64, dims, data.data(), description);
}

void Hdf5Location::write(const std::string& name, const std::vector<std::string>& data,
                         const std::string& description) const {
  const auto type = string_type();
  std::vector<const char*> pointers;
  for (const auto& s : data) pointers.push_back(s.c_str());
  write_dataset(name, type.id(), type.id(), {hsize_t(data.size())}, pointers.data(), description);
}

void Hdf5Location::create_column(const std::string& name, ColumnType type, const ColumnShape& shape,
                                 const std::string& description, const std::string& units) const {
  std::vector<hsize_t> dims{shape.rows};
  if (shape.width > 0) dims.push_back(shape.width);
  if (shape.width > 0 && shape.depth > 0) dims.push_back(shape.depth);
  const Hdf5Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
  const auto dcpl = untimed(H5P_DATASET_CREATE);
  H5Pset_layout(dcpl.id(), H5D_CONTIGUOUS);
  H5Pset_alloc_time(dcpl.id(), H5D_ALLOC_TIME_EARLY);
  H5Pset_fill_time(dcpl.id(), H5D_FILL_TIME_NEVER);
  const auto file_type = [&]() -> Hdf5Handle {
    switch (type) {
      case ColumnType::float64: return Hdf5Handle(H5Tcopy(H5T_IEEE_F64LE), H5Tclose);
      case ColumnType::int64: return Hdf5Handle(H5Tcopy(H5T_STD_I64LE), H5Tclose);
      case ColumnType::flag: return flag_type();
      case ColumnType::text: break;
    }
    return text_type(shape.text_length);
  }();
  const Hdf5Handle set(
      H5Dcreate2(id(), name.c_str(), file_type.id(), space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
      H5Dclose);
  if (set.id() < 0) fail("create dataset", name);
  if (!description.empty()) describe(set.id(), description);
  give_units(set.id(), units);
}

namespace {

/// Selects rows [first, last) of `rows` (ascending) of a dataset of up to three dimensions, one
/// hyperslab per run of consecutive rows, or with `points` every element of each row as a point in the
/// rows' order; false where HDF5 fails.
bool select_rows(hid_t space, int rank, const hsize_t dims[3], const hsize_t* first, const hsize_t* last,
                 bool points) {
  if (points) {
    std::vector<hsize_t> coordinates;
    coordinates.reserve(std::size_t(last - first) * dims[1] * dims[2] * std::size_t(rank));
    for (const hsize_t* row = first; row != last; ++row)
      for (hsize_t j = 0; j < dims[1]; ++j)
        for (hsize_t k = 0; k < dims[2]; ++k) {
          const hsize_t point[3] = {*row, j, k};
          coordinates.insert(coordinates.end(), point, point + rank);
        }
    return H5Sselect_elements(space, H5S_SELECT_SET, coordinates.size() / std::size_t(rank),
                              coordinates.data()) >= 0;
  }
  H5Sselect_none(space);
  for (const hsize_t* run = first; run != last;) {
    const hsize_t* end = run + 1;
    while (end != last && *end == *(end - 1) + 1) ++end;
    const hsize_t start[3] = {*run, 0, 0}, count[3] = {hsize_t(end - run), dims[1], dims[2]};
    if (H5Sselect_hyperslab(space, H5S_SELECT_OR, start, nullptr, count, nullptr) < 0) return false;
    run = end;
  }
  return true;
}

}  // namespace

// HDF5 1.10 unites k hyperslabs in more than k² steps (per column of a 10⁶-row dataset, every fourth
// row: 1 000 take 9 ms, 16 000 7.4 s, 64 000 528 s), and a GPU sweep, whose shadowed members follow
// their shadows' chunks, leaves batches of scattered rows. So a batch of more than 16 runs whose rows
// fill at least an eighth of their span goes as that span: the span read back, the batch's rows laid
// over it, one contiguous write (the rows between keep their bytes). A sparser batch goes as points
// where a row holds a few values (HDF5 selects points in linear time: 0.16 µs per one-value row) and
// otherwise in parts of 16 runs, one H5Dwrite each (3.4 µs per 128-value row, against 16 µs as
// points); docs/performance.md.
void Hdf5Location::write_selected_rows(const std::string& name, const std::vector<hsize_t>& rows,
                                       hid_t memory_type, const void* data) const {
  constexpr std::size_t runs_per_part = 16, most_values_as_points = 8, span_per_row = 8;
  if (rows.empty()) return;
  auto set = open_dataset(name);
  const Hdf5Handle file_space(H5Dget_space(set.id()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(file_space.id());
  if (rank > 3) fail("write rows of", name);
  hsize_t dims[3] = {0, 1, 1};
  H5Sget_simple_extent_dims(file_space.id(), dims, nullptr);
  if (std::any_of(rows.begin(), rows.end(), [&](hsize_t row) { return row >= dims[0]; }))
    fail("select rows of", name);
  std::size_t runs = 1;
  for (std::size_t i = 1; i < rows.size(); ++i) runs += rows[i] != rows[i - 1] + 1;
  const std::size_t row_bytes = H5Tget_size(memory_type) * dims[1] * dims[2];
  const hsize_t span = rows.back() - rows.front() + 1;
  if (runs > runs_per_part && span <= span_per_row * rows.size()) {
    write_span(set.id(), file_space.id(), rank, dims, rows, memory_type, row_bytes, data, name);
    return close_written(std::move(set), name);
  }
  const bool points = runs > runs_per_part && dims[1] * dims[2] <= most_values_as_points;
  for (std::size_t first = 0; first < rows.size();) {
    std::size_t last = first + 1;
    if (points || runs <= runs_per_part)
      last = rows.size();
    else
      for (std::size_t part_runs = 1; last < rows.size(); ++last)
        if (rows[last] != rows[last - 1] + 1 && ++part_runs > runs_per_part) break;
    if (!select_rows(file_space.id(), rank, dims, rows.data() + first, rows.data() + last, points))
      fail("select rows of", name);
    const hsize_t memory_dims[3] = {hsize_t(last - first), dims[1], dims[2]};
    const Hdf5Handle memory_space(H5Screate_simple(rank, memory_dims, nullptr), H5Sclose);
    if (H5Dwrite(set.id(), memory_type, memory_space.id(), file_space.id(), H5P_DEFAULT,
                 static_cast<const char*>(data) + first * row_bytes) < 0)
      fail("write rows of", name);
    first = last;
  }
  close_written(std::move(set), name);
}

void Hdf5Location::write_span(hid_t set, hid_t file_space, int rank, const hsize_t dims[3],
                              const std::vector<hsize_t>& rows, hid_t memory_type, std::size_t row_bytes,
                              const void* data, const std::string& name) const {
  const hsize_t first = rows.front(), span = rows.back() - first + 1;
  const hsize_t start[3] = {first, 0, 0}, count[3] = {span, dims[1], dims[2]};
  if (H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr) < 0)
    fail("select rows of", name);
  const Hdf5Handle memory_space(H5Screate_simple(rank, count, nullptr), H5Sclose);
  std::vector<char> bytes(std::size_t(span) * row_bytes);
  if (H5Dread(set, memory_type, memory_space.id(), file_space, H5P_DEFAULT, bytes.data()) < 0)
    fail("read back rows of", name);
  for (std::size_t i = 0; i < rows.size(); ++i)
    std::memcpy(bytes.data() + (rows[i] - first) * row_bytes, static_cast<const char*>(data) + i * row_bytes,
                row_bytes);
  if (H5Dwrite(set, memory_type, memory_space.id(), file_space, H5P_DEFAULT, bytes.data()) < 0)
    fail("write rows of", name);
}

void Hdf5Location::close_written(Hdf5Handle set, const std::string& name) const {
  // closing writes the dataset's buffered rows: a failure there is a failed write too
  if (H5Dclose(set.release()) < 0) fail("write rows of", name);
}

void Hdf5Location::write_rows(const std::string& name, const std::vector<hsize_t>& rows,
                              const double* data) const {
  write_selected_rows(name, rows, H5T_NATIVE_DOUBLE, data);
}

void Hdf5Location::write_rows(const std::string& name, const std::vector<hsize_t>& rows,
                              const std::int64_t* data) const {
  write_selected_rows(name, rows, H5T_NATIVE_INT64, data);
}

void Hdf5Location::write_rows(const std::string& name, const std::vector<hsize_t>& rows,
                              const signed char* data) const {
  const auto type = flag_type();
  write_selected_rows(name, rows, type.id(), data);
}

void Hdf5Location::write_rows(const std::string& name, const std::vector<hsize_t>& rows,
                              const std::vector<std::string>& data) const {
  const auto set = open_dataset(name);
  const Hdf5Handle type(H5Dget_type(set.id()), H5Tclose);
  const std::size_t length = H5Tget_size(type.id());
  std::vector<char> packed(data.size() * length, '\0');
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (data[i].size() > length)
      fail("write '" + data[i] + "' (longer than " + std::to_string(length) + " bytes) into", name);
    std::copy(data[i].begin(), data[i].end(), packed.begin() + std::ptrdiff_t(i * length));
  }
  write_rows(name, rows, packed.data(), length);
}

void Hdf5Location::write_rows(const std::string& name, const std::vector<hsize_t>& rows, const char* text,
                              std::size_t length) const {
  const auto set = open_dataset(name);
  const Hdf5Handle type(H5Dget_type(set.id()), H5Tclose);
  if (H5Tget_size(type.id()) != length) fail("write text of " + std::to_string(length) + " bytes into", name);
  write_selected_rows(name, rows, type.id(), text);
}

std::string Hdf5Location::column_mismatch(const std::string& name, ColumnType type,
                                          const ColumnShape& shape) const {
  if (!has(name)) return "is missing";
  const auto set = open_dataset(name);
  const Hdf5Handle space(H5Dget_space(set.id()), H5Sclose);
  std::vector<hsize_t> expected{shape.rows};
  if (shape.width > 0) expected.push_back(shape.width);
  if (shape.width > 0 && shape.depth > 0) expected.push_back(shape.depth);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::vector<hsize_t> dims(std::size_t(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  const auto text = [](const std::vector<hsize_t>& d) {
    std::string out = "(";
    for (std::size_t i = 0; i < d.size(); ++i) out += (i ? ", " : "") + std::to_string(d[i]);
    return out + (d.size() == 1 ? ",)" : ")");
  };
  if (dims != expected) return "has shape " + text(dims) + " where its scene gives " + text(expected);
  const Hdf5Handle file_type(H5Dget_type(set.id()), H5Tclose);
  const H5T_class_t kind = H5Tget_class(file_type.id());
  const std::size_t size = H5Tget_size(file_type.id());
  const auto is = [&](H5T_class_t k, std::size_t bytes) { return kind == k && size == bytes; };
  const bool matches =
      type == ColumnType::float64 ? is(H5T_FLOAT, 8)
      : type == ColumnType::int64 ? is(H5T_INTEGER, 8) && H5Tget_sign(file_type.id()) == H5T_SGN_2
      : type == ColumnType::flag  ? is(H5T_ENUM, 1)
                                  : is(H5T_STRING, std::max<std::size_t>(shape.text_length, 1)) &&
                                       H5Tis_variable_str(file_type.id()) == 0;
  if (matches) return "";
  static constexpr const char* names[] = {"64-bit floats", "64-bit integers", "TRUE/FALSE flags",
                                          "fixed-length text"};
  return "does not hold " + std::string(names[int(type)]) + " of " + std::to_string(expected.size()) +
         " dimension" + (expected.size() == 1 ? "" : "s") + " as its scene gives";
}

std::pair<hsize_t, hsize_t> Hdf5Location::shape(const std::string& name) const {
  const auto set = open_dataset(name);
  const Hdf5Handle space(H5Dget_space(set.id()), H5Sclose);
  hsize_t dims[3] = {0, 1, 1};
  if (H5Sget_simple_extent_ndims(space.id()) > 3) fail("read the shape of", name);
  H5Sget_simple_extent_dims(space.id(), dims, nullptr);
  return {dims[0], dims[1] * dims[2]};
}

void Hdf5Location::read_selected_rows(const std::string& name, hsize_t first, hsize_t count,
                                      hid_t memory_type, void* data) const {
  const auto set = open_dataset(name);
  const Hdf5Handle file_space(H5Dget_space(set.id()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(file_space.id());
  hsize_t dims[3] = {0, 1, 1};
  if (rank > 3) fail("read rows of", name);
  H5Sget_simple_extent_dims(file_space.id(), dims, nullptr);
  if (first + count > dims[0]) fail("read rows beyond the end of", name);
  if (count == 0) return;
  const hsize_t start[3] = {first, 0, 0}, counts[3] = {count, dims[1], dims[2]};
  H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start, nullptr, counts, nullptr);
  const Hdf5Handle memory_space(H5Screate_simple(rank, counts, nullptr), H5Sclose);
  if (H5Dread(set.id(), memory_type, memory_space.id(), file_space.id(), H5P_DEFAULT, data) < 0)
    fail("read rows of", name);
}

std::vector<double> Hdf5Location::read_rows_doubles(const std::string& name, hsize_t first,
                                                    hsize_t count) const {
  std::vector<double> data(std::size_t(count * shape(name).second));
  read_selected_rows(name, first, count, H5T_NATIVE_DOUBLE, data.data());
  return data;
}

std::vector<std::int64_t> Hdf5Location::read_rows_integers(const std::string& name, hsize_t first,
                                                           hsize_t count) const {
  std::vector<std::int64_t> data(std::size_t(count * shape(name).second));
  read_selected_rows(name, first, count, H5T_NATIVE_INT64, data.data());
  return data;
}

std::vector<signed char> Hdf5Location::read_flags(const std::string& name) const {
  const hsize_t rows = shape(name).first;
  std::vector<signed char> data(static_cast<std::size_t>(rows));
  const auto type = flag_type();
  read_selected_rows(name, 0, rows, type.id(), data.data());
  return data;
}

std::vector<std::string> Hdf5Location::read_rows_strings(const std::string& name, hsize_t first,
                                                         hsize_t count) const {
  const auto set = open_dataset(name);
  const Hdf5Handle type(H5Dget_type(set.id()), H5Tclose);
  std::vector<std::string> data;
  if (H5Tis_variable_str(type.id()) > 0) {
    const auto text = string_type();
    std::vector<char*> pointers(std::size_t(count), nullptr);
    read_selected_rows(name, first, count, text.id(), pointers.data());
    for (char* p : pointers) data.emplace_back(p ? p : "");
    const hsize_t n = count;
    const Hdf5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    if (count > 0) H5Dvlen_reclaim(text.id(), space.id(), H5P_DEFAULT, pointers.data());
    return data;
  }
  const std::size_t length = H5Tget_size(type.id());
  std::vector<char> packed(std::size_t(count) * length);
  read_selected_rows(name, first, count, type.id(), packed.data());
  for (std::size_t i = 0; i < count; ++i) {
    const char* begin = packed.data() + i * length;
    data.emplace_back(begin, std::find(begin, begin + length, '\0'));
  }
  return data;
}

Hdf5Handle Hdf5Location::open_dataset(const std::string& name) const {
  prepare_hdf5();
  Hdf5Handle set(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.id() < 0) fail("open dataset", name);
  return set;
}

template <class T>
std::vector<T> Hdf5Location::read_numbers(const std::string& name, hid_t memory_type,
                                          std::vector<hsize_t>* dims) const {
  const auto set = open_dataset(name);
  const Hdf5Handle space(H5Dget_space(set.id()), H5Sclose);
  std::vector<T> data(std::size_t(H5Sget_simple_extent_npoints(space.id())));
  if (dims) {
    dims->resize(std::size_t(H5Sget_simple_extent_ndims(space.id())));
    H5Sget_simple_extent_dims(space.id(), dims->data(), nullptr);
  }
  if (H5Dread(set.id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail("read dataset", name);
  return data;
}

std::vector<double> Hdf5Location::read_doubles(const std::string& name, std::vector<hsize_t>* dims) const {
  return read_numbers<double>(name, H5T_NATIVE_DOUBLE, dims);
}

std::vector<std::int64_t> Hdf5Location::read_integers(const std::string& name) const {
  return read_numbers<std::int64_t>(name, H5T_NATIVE_INT64, nullptr);
}

std::vector<std::string> Hdf5Location::read_strings(const std::string& name) const {
  return read_rows_strings(name, 0, shape(name).first);
}

std::vector<unsigned char> Hdf5Location::read_bytes(const std::string& name) const {
  const auto set = open_dataset(name);
  const Hdf5Handle type(H5Dget_type(set.id()), H5Tclose);
  if (H5Tis_variable_str(type.id()) > 0) {
    std::vector<unsigned char> bytes;
    for (const auto& s : read_strings(name)) {
      bytes.insert(bytes.end(), s.begin(), s.end());
      bytes.push_back(0);
    }
    return bytes;
  }
  const Hdf5Handle space(H5Dget_space(set.id()), H5Sclose);
  std::vector<unsigned char> bytes(std::size_t(H5Sget_simple_extent_npoints(space.id())) *
                                   H5Tget_size(type.id()));
  if (H5Dread(set.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0)
    fail("read dataset", name);
  return bytes;
}

void Hdf5Location::set_attribute(const std::string& name, double value) const {
  const auto attribute = fresh_attribute(id(), name, H5T_IEEE_F64LE);
  if (attribute.id() < 0 || H5Awrite(attribute.id(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail("write attribute", name);
}

void Hdf5Location::set_attribute(const std::string& name, std::int64_t value) const {
  const auto attribute = fresh_attribute(id(), name, H5T_STD_I64LE);
  if (attribute.id() < 0 || H5Awrite(attribute.id(), H5T_NATIVE_INT64, &value) < 0)
    fail("write attribute", name);
}

void Hdf5Location::set_attribute(const std::string& name, const std::string& value) const {
  if (write_string_attribute(id(), name, value) < 0) fail("write attribute", name);
}

void Hdf5Location::set_flag(const std::string& name, bool value) const {
  const auto type = flag_type();
  const auto attribute = fresh_attribute(id(), name, type.id());
  const signed char stored = value ? 1 : 0;
  if (attribute.id() < 0 || H5Awrite(attribute.id(), type.id(), &stored) < 0) fail("write attribute", name);
}

void Hdf5Location::remove_attribute(const std::string& name) const {
  if (has_attribute(name) && H5Adelete(id(), name.c_str()) < 0) fail("remove attribute", name);
}

bool Hdf5Location::has_attribute(const std::string& name) const { return H5Aexists(id(), name.c_str()) > 0; }

double Hdf5Location::attribute_double(const std::string& name) const {
  const Hdf5Handle attribute(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  double value = 0;
  if (attribute.id() < 0 || H5Aread(attribute.id(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail("read attribute", name);
  return value;
}

std::string Hdf5Location::attribute_string(const std::string& name) const {
  const Hdf5Handle attribute(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  const auto type = string_type();
  char* pointer = nullptr;
  if (attribute.id() < 0 || H5Aread(attribute.id(), type.id(), &pointer) < 0) fail("read attribute", name);
  std::string value = pointer ? pointer : "";
  H5free_memory(pointer);
  return value;
}

bool Hdf5Location::attribute_flag(const std::string& name) const {
  const Hdf5Handle attribute(H5Aopen(id(), name.c_str(), H5P_DEFAULT), H5Aclose);
  const auto type = flag_type();
  signed char value = 0;
  if (attribute.id() < 0 || H5Aread(attribute.id(), type.id(), &value) < 0) fail("read attribute", name);
  return value != 0;
}

}  // namespace rotorsweep::io
