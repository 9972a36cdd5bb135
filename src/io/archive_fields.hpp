#pragma once
// One list of fields for both save and load, as Discs::for_each_array is for discs: a state
// struct lists each field once with its key, in a function template
//   template <class Self, class F> static void fields(Self& self, F&& f) { f("key", self.member); ... }
// and save() / load() pass it an ArchiveSaver or an ArchiveLoader. The key and the type of a
// field are then written once, so a save and its load cannot drift apart. Kinds of field:
// an arithmetic scalar (a bool as one byte), a string, a std::vector of archive elements, a
// std::array<double, N> (stored as a vector), and the columns of a table (a std::vector of rows):
//   column(rows, m): m of every row, m a member pointer or a callable returning a reference into the row (a bool as uint8);
//   flat_column(rows, m, width): a vector member of `width` values a row, row-major (row j, value i at j * width + i);
//   keyed_rows(map, list): a map from key to row: its keys, then the columns `list(rows, f)` lists, in the map's order.
// A load sizes an empty table by its first column; every other column must fit it.
#include <algorithm>
#include <array>
#include <concepts>
#include <cstdint>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/binary_archive.hpp"

namespace orogen {

template <class Rows, class Member>
struct RowColumn {
  Rows& rows;
  Member member;
};
template <class Rows, class Member>
RowColumn<Rows, Member> column(Rows& rows, Member member) {
  return {rows, member};
}

template <class Rows, class Member>
struct FlatColumn {
  Rows& rows;
  Member member;
  std::size_t width;
};
template <class Rows, class Member>
FlatColumn<Rows, Member> flat_column(Rows& rows, Member member, std::size_t width) {
  return {rows, member, width};
}

template <class Map, class List>
struct KeyedRows {
  Map& map;
  List list;
};
template <class Map, class List>
KeyedRows<Map, List> keyed_rows(Map& map, List list) {
  return {map, list};
}

namespace archive_detail {

// A saved keyed table refers to the map's rows rather than copying them.
template <class Row>
const Row& row_of(const Row& r) {
  return r;
}
template <class Row>
Row& row_of(const std::reference_wrapper<Row>& r) {
  return r.get();
}

// What a column holds per row, and what the file stores of it.
template <class Rows, class Member>
using Cell = std::remove_cvref_t<decltype(std::invoke(std::declval<Member&>(), row_of(std::declval<Rows&>().front())))>;
template <class T>
using Stored = std::conditional_t<std::same_as<T, bool>, std::uint8_t, T>;

}  // namespace archive_detail

class ArchiveSaver {
 public:
  explicit ArchiveSaver(ArchiveWriter& out) : out_(out) {}

  template <class T>
  void operator()(std::string_view key, const T& v) const {
    if constexpr (std::same_as<T, bool>) {
      out_.put_scalar<std::uint8_t>(key, v ? 1 : 0);
    } else if constexpr (std::same_as<T, std::string>) {
      out_.put_string(key, v);
    } else if constexpr (ArchiveScalar<T>) {
      out_.put_scalar(key, v);
    } else if constexpr (requires { typename std::tuple_size<T>::type; }) {
      out_.put(key, std::vector<typename T::value_type>(v.begin(), v.end()));
    } else {
      out_.put(key, v);
    }
  }
  template <class Rows, class Member>
  void operator()(std::string_view key, const RowColumn<Rows, Member>& c) const {
    std::vector<archive_detail::Stored<archive_detail::Cell<Rows, Member>>> col;
    for (const auto& r : c.rows) col.push_back(std::invoke(c.member, archive_detail::row_of(r)));
    out_.put(key, col);
  }
  template <class Rows, class Member>
  void operator()(std::string_view key, const FlatColumn<Rows, Member>& c) const {
    archive_detail::Cell<Rows, Member> flat;
    for (const auto& r : c.rows) {
      const auto& values = std::invoke(c.member, archive_detail::row_of(r));
      flat.insert(flat.end(), values.begin(), values.end());
    }
    out_.put(key, flat);
  }
  template <class Map, class List>
  void operator()(std::string_view key, const KeyedRows<Map, List>& t) const {
    std::vector<typename Map::key_type> keys;
    std::vector<std::reference_wrapper<const typename Map::mapped_type>> rows;
    for (const auto& [k, row] : t.map) {
      keys.push_back(k);
      rows.push_back(std::cref(row));
    }
    out_.put(key, keys);
    t.list(rows, *this);
  }

 private:
  ArchiveWriter& out_;
};

class ArchiveLoader {
 public:
  explicit ArchiveLoader(const ArchiveReader& in) : in_(in) {}

  template <class T>
  void operator()(std::string_view key, T& v) const {
    if constexpr (std::same_as<T, bool>) {
      v = in_.get_scalar<std::uint8_t>(key) != 0;
    } else if constexpr (std::same_as<T, std::string>) {
      v = in_.get_string(key);
    } else if constexpr (ArchiveScalar<T>) {
      v = in_.get_scalar<T>(key);
    } else if constexpr (requires { typename std::tuple_size<T>::type; }) {
      std::vector<typename T::value_type> got;
      in_.get(key, got);
      std::copy_n(got.begin(), std::min(v.size(), got.size()), v.begin());
    } else {
      in_.get(key, v);
    }
  }
  template <class Rows, class Member>
  void operator()(std::string_view key, RowColumn<Rows, Member> c) const {
    using Cell = archive_detail::Cell<Rows, Member>;
    std::vector<archive_detail::Stored<Cell>> got;
    in_.get(key, got);
    if (c.rows.empty()) c.rows.resize(got.size());
    expect_values(key, got.size(), c.rows.size(), 1);
    for (std::size_t k = 0; k < got.size(); ++k) std::invoke(c.member, c.rows[k]) = static_cast<Cell>(got[k]);
  }
  template <class Rows, class Member>
  void operator()(std::string_view key, FlatColumn<Rows, Member> c) const {
    archive_detail::Cell<Rows, Member> got;
    in_.get(key, got);
    expect_values(key, got.size(), c.rows.size(), c.width);
    const auto at = [&](std::size_t j) { return got.begin() + static_cast<std::ptrdiff_t>(j * c.width); };
    for (std::size_t j = 0; j < c.rows.size(); ++j) std::invoke(c.member, c.rows[j]).assign(at(j), at(j + 1));
  }
  // Into an empty map, in the file's order and not reserved: the order the map then goes
  // through its rows in (and the next save writes) is the one loads have always given.
  template <class Map, class List>
  void operator()(std::string_view key, KeyedRows<Map, List> t) const {
    std::vector<typename Map::key_type> keys;
    in_.get(key, keys);
    std::vector<typename Map::mapped_type> rows(keys.size());
    t.list(rows, *this);
    expect_values(key, keys.size(), rows.size(), 1);  // a table of no keys but some rows
    for (std::size_t k = 0; k < keys.size(); ++k)
      if (!t.map.emplace(keys[k], std::move(rows[k])).second) fail(key, "holds a key twice");
  }

 private:
  void expect_values(std::string_view key, std::size_t values, std::size_t rows, std::size_t width) const {
    if (values != rows * width)
      fail(key, "has " + std::to_string(values) + " values, not " + std::to_string(rows * width) + " (" +
                    std::to_string(rows) + " rows of " + std::to_string(width) + ")");
  }
  [[noreturn]] void fail(std::string_view key, const std::string& what) const {
    throw std::runtime_error("archive '" + in_.path().string() + "' record '" + std::string(key) + "' " + what);
  }
  const ArchiveReader& in_;
};

}  // namespace orogen
