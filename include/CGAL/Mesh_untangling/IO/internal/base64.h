// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Base64 text decoded a given number of bytes at a time (XML VTK's binary data).
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_BASE64_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_BASE64_H

#include <cstddef>
#include <string>
#include <string_view>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// Decodes four characters at a time.  Padding ends a group, not the text:
// VTK encodes the header of an array and its data apart, one after the
// other, so a '=' may stand in the middle.  Blanks between groups are
// skipped; a '<' (the tag after the data) or the end of the text ends it.
class Base64_reader
{
public:
  Base64_reader(std::string_view text, std::size_t start) : text_(text), pos_(start) {}

  /// Appends the next `n` decoded bytes to `out`; false (see error()) if the
  /// text ends first or holds something that is not base64.
  bool take(std::size_t n, std::string& out)
  {
    while(pending_.size() - used_ < n)
      if(!decode_group())
        return false;
    out.append(pending_, used_, n);
    used_ += n;
    if(used_ == pending_.size()) {
      pending_.clear();
      used_ = 0;
    }
    return true;
  }

  /// At most this many bytes remain (to check a size read before allocating).
  std::size_t remaining_bound() const { return (text_.size() - pos_) / 4 * 3 + pending_.size() - used_; }

  /// The offset in the text of the group being decoded, for messages.
  std::size_t position() const { return pos_; }

  /// Why take() failed: "truncated" or the bad character.
  const std::string& error() const { return error_; }

private:
  static int value_of(char c)
  {
    if(c >= 'A' && c <= 'Z') return c - 'A';
    if(c >= 'a' && c <= 'z') return c - 'a' + 26;
    if(c >= '0' && c <= '9') return c - '0' + 52;
    if(c == '+') return 62;
    if(c == '/') return 63;
    return -1;
  }

  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

  bool decode_group()
  {
    int values[4];
    int padding = 0;
    for(int i = 0; i < 4; ++i) {
      while(pos_ < text_.size() && is_space(text_[pos_]))
        ++pos_;
      if(pos_ == text_.size() || text_[pos_] == '<') {
        error_ = "truncated";
        return false;
      }
      const char c = text_[pos_];
      values[i] = c == '=' && i >= 2 ? 0 : value_of(c);
      if(c == '=' && i >= 2)
        ++padding;
      if(values[i] < 0 || (padding > 0 && c != '=')) {
        const unsigned char u = static_cast<unsigned char>(c);
        error_ = "bad base64 character " + (u >= 32 && u < 127 ? "'" + std::string(1, c) + "'" : std::string("byte ")
                                                                                               + std::to_string(u));
        return false;
      }
      ++pos_;
    }
    const unsigned long bits = (static_cast<unsigned long>(values[0]) << 18) | (static_cast<unsigned long>(values[1]) << 12)
                               | (static_cast<unsigned long>(values[2]) << 6) | static_cast<unsigned long>(values[3]);
    const char bytes[3] = {static_cast<char>((bits >> 16) & 0xFF), static_cast<char>((bits >> 8) & 0xFF),
                           static_cast<char>(bits & 0xFF)};
    pending_.append(bytes, static_cast<std::size_t>(3 - padding));
    return true;
  }

  std::string_view text_;
  std::size_t pos_;
  std::string pending_;
  std::size_t used_ = 0;
  std::string error_;
};

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_BASE64_H
