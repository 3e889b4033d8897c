// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cursor that reads a Gmsh .msh file: its text lines and words, and, in a
// binary file, the raw integers and doubles between them.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_STREAM_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_STREAM_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/Text_file.h>
#include <CGAL/Mesh_untangling/IO/internal/number_parsing.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Where something is in the file: its line, which only text files can name
// (a binary block may hold any byte, '\n' too), and its byte offset.
struct GMSH_place
{
  std::size_t line = 0;
  std::size_t offset = 0;
};

// Text_file cannot serve here: a binary .msh file mixes text lines (section
// names, $PhysicalNames, the counts of MSH 2.2) with raw numbers.  Errors name
// the line in a text file, the byte offset in a binary one.
class GMSH_stream
{
public:
  explicit GMSH_stream(const std::string& path) : path_(path), bytes_(read_whole_file(path)) {}

  const std::string& path() const { return path_; }
  bool binary() const { return binary_; }

  // From the $MeshFormat line on, the numbers of the data blocks are raw,
  // in the byte order of the file (`swap`: not the machine's).
  void set_binary(bool swap)
  {
    binary_ = true;
    swap_ = swap;
  }

  GMSH_place place() const { return GMSH_place{line_, pos_}; }

  std::size_t remaining() const { return bytes_.size() - pos_; }

  /// For reserve(): a count read from the file is believed only as far as
  /// the bytes left can hold items of at least `item_bytes`.
  std::size_t sane_capacity(std::size_t count, std::size_t item_bytes) const
  {
    return (std::min)(count, remaining() / item_bytes + 1);
  }

  /// The next line with text, without its blanks around; false at the end.
  bool next_line(std::string_view& text, GMSH_place& at)
  {
    for(;;) {
      skip_blanks(true);
      if(pos_ == bytes_.size())
        return false;
      at = place();
      std::size_t end = bytes_.find('\n', pos_);
      if(end == std::string::npos)
        end = bytes_.size();
      text = trimmed(std::string_view(bytes_).substr(pos_, end - pos_));
      pos_ = end;
      if(!text.empty())
        return true;
    }
  }

  /// The next blank-separated word of text, whatever line it is on.
  bool next_word(std::string_view& word, GMSH_place& at)
  {
    skip_blanks(true);
    if(pos_ == bytes_.size())
      return false;
    at = place();
    const std::size_t begin = pos_;
    while(pos_ < bytes_.size() && !is_blank(bytes_[pos_]) && bytes_[pos_] != '\n')
      ++pos_;
    word = std::string_view(bytes_).substr(begin, pos_ - begin);
    return true;
  }

  /// The rest of the current line, without its blanks around.
  std::string_view rest_of_line()
  {
    std::size_t end = bytes_.find('\n', pos_);
    if(end == std::string::npos)
      end = bytes_.size();
    const std::string_view text = trimmed(std::string_view(bytes_).substr(pos_, end - pos_));
    pos_ = end;
    return text;
  }

  /// Skips to the line after the next one that reads `end_line` (for the
  /// sections not needed, text or binary): false if there is none.
  bool skip_to_line(std::string_view end_line)
  {
    std::size_t from = pos_;
    for(;;) {
      const std::size_t found = bytes_.find(end_line, from);
      if(found == std::string::npos)
        return false;
      const std::size_t after = found + end_line.size();
      const bool starts_line = found == 0 || bytes_[found - 1] == '\n';
      const bool ends_line = after == bytes_.size() || bytes_[after] == '\n' || bytes_[after] == '\r'
                             || is_blank(bytes_[after]);
      if(starts_line && ends_line) {
        line_ += static_cast<std::size_t>(std::count(bytes_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                     bytes_.begin() + static_cast<std::ptrdiff_t>(found), '\n'));
        pos_ = found;
        rest_of_line();
        return true;
      }
      from = found + 1;
    }
  }

  /// Ends the text line before a block of raw numbers, which starts right
  /// after its '\n'.
  void begin_binary_data(const std::string& block)
  {
    const GMSH_place at = place();
    const std::string_view rest = rest_of_line();
    if(!rest.empty())
      fail(at, "unexpected text " + quote_token(rest) + " before the binary data of " + block);
    if(pos_ < bytes_.size()) {
      ++pos_;
      ++line_;
    }
  }

  // ---- numbers: text words, or raw bytes in a binary data block ----------

  /// A non-negative integer of text (counts, tags, dimensions).
  template <class Describe>
  std::size_t text_size(const Describe& describe)
  {
    const std::string_view word = text_word(describe);
    std::size_t value = 0;
    if(!parse_size(word, value))
      fail(last_, describe() + " is not a non-negative integer: " + quote_token(word));
    return value;
  }

  template <class Describe>
  long long text_integer(const Describe& describe)
  {
    const std::string_view word = text_word(describe);
    long long value = 0;
    if(!parse_integer(word, value))
      fail(last_, describe() + " is not an integer: " + quote_token(word));
    return value;
  }

  template <class Describe>
  double text_double(const Describe& describe)
  {
    const std::string_view word = text_word(describe);
    double value = 0;
    switch(parse_double(word, value)) {
      case Number_status::OK:
        return value;
      case Number_status::NOT_FINITE:
        fail(last_, describe() + " is not finite: " + quote_token(word));
      default:
        fail(last_, describe() + " is not a number: " + quote_token(word));
    }
  }

  /// A size_t of the data (8 bytes in a binary file: $MeshFormat's data-size).
  template <class Describe>
  std::size_t size(const Describe& describe)
  {
    if(!binary_)
      return text_size(describe);
    return static_cast<std::size_t>(raw<std::uint64_t>(describe));
  }

  /// An int of the data (4 bytes in a binary file); negative values are errors
  /// when `non_negative`.
  template <class Describe>
  long long integer(const Describe& describe, bool non_negative = true)
  {
    long long value = 0;
    if(!binary_)
      value = text_integer(describe);
    else
      value = static_cast<std::int32_t>(raw<std::uint32_t>(describe));
    if(non_negative && value < 0)
      fail(last_, describe() + " is negative: " + std::to_string(value));
    return value;
  }

  template <class Describe>
  double real(const Describe& describe)
  {
    if(!binary_)
      return text_double(describe);
    const std::uint64_t bits = raw<std::uint64_t>(describe);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    if(!(value - value == 0))
      fail(last_, describe() + " is not finite");
    return value;
  }

  /// The place of the number last read, for messages about its value.
  GMSH_place last_place() const { return last_; }

  [[noreturn]] void fail(const GMSH_place& at, const std::string& reason) const
  {
    if(binary_)
      throw Read_error(path_, 0, "at byte " + std::to_string(at.offset) + ": " + reason);
    throw Read_error(path_, at.line, reason);
  }

  /// The end of the file came before `what`.
  /// (at the end of a text file: on its last line with text)
  [[noreturn]] void fail_truncated(const std::string& what) const
  {
    GMSH_place at = place();
    if(pos_ == bytes_.size() && !binary_) {
      const std::size_t last = bytes_.find_last_not_of(" \t\r\v\f\n");
      const std::ptrdiff_t end = static_cast<std::ptrdiff_t>(last == std::string::npos ? 0 : last);
      at.line = 1 + static_cast<std::size_t>(std::count(bytes_.begin(), bytes_.begin() + end, '\n'));
    }
    fail(at, "truncated: " + what);
  }

private:
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  static std::string_view trimmed(std::string_view text)
  {
    while(!text.empty() && (is_blank(text.front()) || text.front() == '\0'))
      text.remove_prefix(1);
    while(!text.empty() && (is_blank(text.back()) || text.back() == '\0'))
      text.remove_suffix(1);
    return text;
  }

  // (a UTF-8 byte order mark, as editors on Windows prepend, counts as blank)
  void skip_blanks(bool newlines)
  {
    if(pos_ == 0 && bytes_.compare(0, 3, "\xEF\xBB\xBF") == 0)
      pos_ = 3;
    while(pos_ < bytes_.size() && (is_blank(bytes_[pos_]) || (newlines && bytes_[pos_] == '\n'))) {
      if(bytes_[pos_] == '\n')
        ++line_;
      ++pos_;
    }
  }

  template <class Describe>
  std::string_view text_word(const Describe& describe)
  {
    std::string_view word;
    if(!next_word(word, last_))
      fail_truncated("expected the " + describe());
    // A section's end where a number should be: the section holds fewer
    // items than its counts announced.
    if(word[0] == '$')
      fail(last_, "truncated section: found " + quote_token(word) + " where the " + describe() + " should be");
    return word;
  }

  template <class Unsigned, class Describe>
  Unsigned raw(const Describe& describe)
  {
    last_ = place();
    if(remaining() < sizeof(Unsigned))
      fail(last_, "truncated: the file ends before the " + describe());
    unsigned char b[sizeof(Unsigned)];
    std::memcpy(b, bytes_.data() + pos_, sizeof b);
    pos_ += sizeof b;
    if(swap_)
      std::reverse(b, b + sizeof b);
    Unsigned value;
    std::memcpy(&value, b, sizeof value);
    return value;
  }

  std::string path_;
  std::string bytes_;
  bool binary_ = false;
  bool swap_ = false;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  GMSH_place last_;
};

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_STREAM_H
