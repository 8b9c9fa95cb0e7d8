// The columns of a pre-sized table (docs/output.md "Output file"): name, type, shape, description and how a
// row is packed from what one member produced, so that creating a file and writing its rows share one list.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// One column (`name` is a path below the table's location, e.g. "periods/dissipation"), filled from
/// a member's `Row` values. Exactly one of real (writes max(1, width) · max(1, depth) values, NaN
/// where it writes none), integer and text fills a row, matching `type`.
template <class... Row>
struct TableColumn {
  std::string name;
  ColumnType type = ColumnType::float64;
  hsize_t width = 0;  ///< 0: one value per member
  std::size_t text_length = 0;
  std::string description;
  std::function<void(const Row&..., double*)> real;
  std::function<std::int64_t(const Row&...)> integer;
  std::function<std::string(const Row&...)> text;
  hsize_t depth = 0;        ///< > 0 (with width > 0): a width × depth block per member
  std::string units = "1";  ///< of a numeric column (UDUNITS spelling; "1": dimensionless)

  /// The same column with other units.
  TableColumn in_units(std::string u) && {
    units = std::move(u);
    return std::move(*this);
  }

  /// Values per member.
  std::size_t values() const {
    return std::size_t(std::max<hsize_t>(width, 1) * std::max<hsize_t>(depth, 1));
  }

  static TableColumn real_valued(std::string name, std::string description,
                                 std::function<double(const Row&...)> value) {
    TableColumn c{std::move(name), ColumnType::float64, 0, 0, std::move(description), {}, {}, {}};
    c.real = [value = std::move(value)](const Row&... row, double* out) { *out = value(row...); };
    return c;
  }
  static TableColumn integer_valued(std::string name, std::string description,
                                    std::function<std::int64_t(const Row&...)> value) {
    TableColumn c{std::move(name), ColumnType::int64, 0, 0, std::move(description), {}, {}, {}};
    c.integer = std::move(value);
    return c;
  }
  static TableColumn text_valued(std::string name, std::size_t length, std::string description,
                                 std::function<std::string(const Row&...)> value) {
    TableColumn c{std::move(name), ColumnType::text, 0, length, std::move(description), {}, {}, {}};
    c.text = std::move(value);
    return c;
  }
  /// A (members × width) column whose row is a vector, NaN beyond its length; with depth > 0 a
  /// (members × width × depth) column whose row is the vector's first width · depth values.
  static TableColumn vector_valued(std::string name, hsize_t width, std::string description,
                                   std::function<std::vector<double>(const Row&...)> value,
                                   hsize_t depth = 0) {
    TableColumn c{std::move(name), ColumnType::float64, width, 0, std::move(description), {}, {}, {}, depth};
    const std::size_t n = c.values();
    c.real = [value = std::move(value), n](const Row&... row, double* out) {
      const auto values = value(row...);
      std::copy_n(values.begin(), std::min(values.size(), n), out);
    };
    return c;
  }
};

/// Bytes one member's row takes over all columns.
template <class... Row>
double table_row_bytes(const std::vector<TableColumn<Row...>>& columns) {
  double bytes = 0;
  for (const auto& column : columns)
    bytes += double(column.values()) * double(column.type == ColumnType::text ? column.text_length : 8);
  return bytes;
}

/// Creates every column with `rows` rows below `at`, and the groups their names pass through.
template <class... Row>
void create_table_columns(const Hdf5Location& at, const std::vector<TableColumn<Row...>>& columns,
                          hsize_t rows) {
  for (const auto& column : columns) {
    for (std::size_t slash = column.name.find('/'); slash != std::string::npos;
         slash = column.name.find('/', slash + 1))
      if (const std::string group = column.name.substr(0, slash); !at.has(group)) at.create_group(group);
    at.create_column(column.name, column.type, {rows, column.width, column.text_length, column.depth},
                     column.description, column.units);
  }
}

/// Throws std::runtime_error naming the first of `columns` whose dataset below `at` (in the file at
/// `path`, the columns' location `where`, e.g. "/members/") is missing or is not what
/// create_table_columns makes for `rows` rows: a file written for another scene, or edited.
template <class... Row>
void check_table_columns(const Hdf5Location& at, const std::vector<TableColumn<Row...>>& columns,
                         hsize_t rows, const std::string& path, const std::string& where) {
  for (const auto& column : columns)
    if (const std::string mismatch = at.column_mismatch(
            column.name, column.type, {rows, column.width, column.text_length, column.depth});
        !mismatch.empty())
      throw std::runtime_error("'" + path + "': dataset " + where + column.name + " " + mismatch +
                               ": the file does not hold its scene's results");
}

/// One member's values of every column, in column order, as the file holds them (8-byte numbers, text
/// padded with NUL to its length): taken on the thread where the member finished, so that the thread
/// writing a batch only gathers bytes.
struct PackedRow {
  std::size_t index = 0;  ///< the plan index of the member whose row it is
  std::vector<char> bytes;
};

/// Bytes a column's value takes in a packed row (flags, which no member fills, none).
template <class... Row>
std::size_t packed_bytes(const TableColumn<Row...>& column) {
  switch (column.type) {
    case ColumnType::float64: return 8 * column.values();
    case ColumnType::int64: return 8;  // integer() gives one value per member
    case ColumnType::text: return std::max<std::size_t>(column.text_length, 1);
    case ColumnType::flag: break;
  }
  return 0;
}

/// The values of every column for one member (`row`...); throws std::runtime_error where a text is longer
/// than its column's length.
template <class... Row>
std::vector<char> pack_table_row(const std::vector<TableColumn<Row...>>& columns, const Row&... row) {
  std::size_t size = 0;
  for (const auto& column : columns) size += packed_bytes(column);
  std::vector<char> bytes(size, '\0');
  std::vector<double> reals;
  char* out = bytes.data();
  for (const auto& column : columns) {
    switch (column.type) {
      case ColumnType::float64: {
        reals.assign(column.values(), std::numeric_limits<double>::quiet_NaN());
        column.real(row..., reals.data());
        std::memcpy(out, reals.data(), 8 * reals.size());
        break;
      }
      case ColumnType::int64: {
        const std::int64_t value = column.integer(row...);
        std::memcpy(out, &value, 8);
        break;
      }
      case ColumnType::text: {
        const std::string text = column.text(row...);
        if (text.size() > packed_bytes(column))
          throw std::runtime_error("cannot write '" + text + "' (longer than " +
                                   std::to_string(packed_bytes(column)) + " bytes) into column " +
                                   column.name);
        std::memcpy(out, text.data(), text.size());
        break;
      }
      case ColumnType::flag: break;
    }
    out += packed_bytes(column);
  }
  return bytes;
}

/// Writes packed[i] into row rows[i] of every column (rows ascending): each column's values gathered from
/// the packed rows, one write per column.
template <class... Row>
void write_packed_rows(const Hdf5Location& at, const std::vector<TableColumn<Row...>>& columns,
                       const std::vector<hsize_t>& rows, const std::vector<const PackedRow*>& packed) {
  std::size_t offset = 0;
  for (const auto& column : columns) {
    const std::size_t bytes = packed_bytes(column), n = packed.size();
    const auto gather = [&](void* into) {
      for (std::size_t i = 0; i < n; ++i)
        std::memcpy(static_cast<char*>(into) + i * bytes, packed[i]->bytes.data() + offset, bytes);
    };
    switch (column.type) {
      case ColumnType::float64: {
        std::vector<double> values(n * column.values());
        gather(values.data());
        at.write_rows(column.name, rows, values.data());
        break;
      }
      case ColumnType::int64: {
        std::vector<std::int64_t> values(n);
        gather(values.data());
        at.write_rows(column.name, rows, values.data());
        break;
      }
      case ColumnType::text: {
        std::vector<char> text(n * bytes);
        gather(text.data());
        at.write_rows(column.name, rows, text.data(), bytes);
        break;
      }
      case ColumnType::flag: break;
    }
    offset += bytes;
  }
}

/// Writes member i (values[i]... of each Row) into row rows[i] of every column (rows ascending).
template <class... Row>
void write_table_rows(const Hdf5Location& at, const std::vector<TableColumn<Row...>>& columns,
                      const std::vector<hsize_t>& rows, const std::vector<Row>&... values) {
  std::vector<PackedRow> packed(rows.size());
  std::vector<const PackedRow*> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    packed[i].bytes = pack_table_row(columns, values[i]...);
    order.push_back(&packed[i]);
  }
  write_packed_rows(at, columns, rows, order);
}

}  // namespace rotorsweep::io
