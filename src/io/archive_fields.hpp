#pragma once
// One list of fields for both save and load, as Discs::for_each_array is for discs: a state
// struct lists each field once with its key, in a function template
//   template <class Self, class F> static void fields(Self& self, F&& f) { f("key", self.member); ... }
// and save() / load() pass it an ArchiveSaver or an ArchiveLoader. The key and the type of a
// field are then written once, so a save and its load cannot drift apart. Kinds of field:
// an arithmetic scalar (a bool as one byte), a string, a std::vector of archive elements, a std::array<double, N> (stored as
// a vector), and a column of a vector of rows (`column(rows, &Row::member)`).
#include <algorithm>
#include <array>
#include <concepts>
#include <cstdint>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/binary_archive.hpp"

namespace orogen {

// One member of every row of a vector of rows, stored as one vector.
template <class Rows, class Member>
struct RowColumn {
  Rows& rows;
  Member member;
};
template <class Rows, class Member>
RowColumn<Rows, Member> column(Rows& rows, Member member) {
  return {rows, member};
}

template <class T>
struct IsRowColumn : std::false_type {};
template <class Rows, class Member>
struct IsRowColumn<RowColumn<Rows, Member>> : std::true_type {};

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
    } else if constexpr (IsRowColumn<T>::value) {
      using Value = std::remove_cvref_t<decltype(v.rows.front().*v.member)>;
      std::vector<Value> col;
      for (const auto& r : v.rows) col.push_back(r.*v.member);
      out_.put(key, col);
    } else if constexpr (requires { typename std::tuple_size<T>::type; }) {
      out_.put(key, std::vector<typename T::value_type>(v.begin(), v.end()));
    } else {
      out_.put(key, v);
    }
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
  // A column sizes the rows to its length (every column of a set has the same).
  template <class Rows, class Member>
  void operator()(std::string_view key, RowColumn<Rows, Member> c) const {
    using Value = std::remove_cvref_t<decltype(c.rows.front().*c.member)>;
    std::vector<Value> got;
    in_.get(key, got);
    c.rows.resize(got.size());
    for (std::size_t k = 0; k < got.size(); ++k) c.rows[k].*c.member = got[k];
  }

 private:
  const ArchiveReader& in_;
};

}  // namespace orogen
