// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tags of an XML VTK file, one at a time, with their lines.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_XML_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_XML_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct XML_tag
{
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;   // entities decoded
  bool closing = false;        // </name>
  bool self_closing = false;   // <name ... />
  std::size_t line = 0;

  const std::string* attribute(const char* key) const
  {
    for(const auto& a : attributes)
      if(a.first == key)
        return &a.second;
    return nullptr;
  }
};

// A scanner rather than an XML library (Boost.PropertyTree's parser is at
// hand): an appended block is raw bytes after its '_', which no XML parser
// takes, and a reader's errors name lines, which a parsed tree has lost.
// VTK files use no more of XML than tags, attributes, text, comments, the
// declaration and the five predefined entities.
class XML_scanner
{
public:
  XML_scanner(std::string path, std::string_view bytes) : path_(std::move(path)), bytes_(bytes)
  {
    // (a UTF-8 byte order mark, as editors on Windows prepend)
    if(bytes_.substr(0, 3) == "\xEF\xBB\xBF")
      pos_ = 3;
  }

  const std::string& path() const { return path_; }
  std::size_t line() const { return line_; }
  std::size_t position() const { return pos_; }

  /// The next tag, past text, comments, the declaration and a DOCTYPE; false at the end.
  bool next_tag(XML_tag& tag)
  {
    for(;;) {
      if(!advance_to('<'))
        return false;
      const std::size_t start_line = line_;
      if(starts_with("<!--"))
        skip_past("-->", start_line, "a comment");
      else if(starts_with("<?"))
        skip_past("?>", start_line, "an XML declaration");
      else if(starts_with("<!"))
        skip_past(">", start_line, "a <!...> declaration");
      else
        return read_tag(tag);
    }
  }

  /// The text from here to the next tag (the values of an ASCII or a base64
  /// DataArray), and the line it starts on; the scanner stays where it is.
  std::string_view text(std::size_t& line) const
  {
    line = line_;
    std::size_t end = bytes_.find('<', pos_);
    if(end == std::string_view::npos)
      end = bytes_.size();
    return bytes_.substr(pos_, end - pos_);
  }

  /// Past the blanks after <AppendedData ...>, the '_' that starts the data:
  /// the byte offset after it.
  std::size_t appended_data_start()
  {
    while(pos_ < bytes_.size() && is_space(bytes_[pos_]))
      step();
    if(pos_ == bytes_.size())
      fail_truncated("expected the '_' that starts the appended data");
    if(bytes_[pos_] != '_')
      fail(line_, "expected the '_' that starts the appended data, got " + quote_token(bytes_.substr(pos_, 1)));
    return pos_ + 1;
  }

  [[noreturn]] void fail(std::size_t line, const std::string& reason) const { throw Read_error(path_, line, reason); }

  [[noreturn]] void fail_truncated(const std::string& what) const { fail(line_, "truncated: " + what); }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

  bool starts_with(const char* s) const { return bytes_.compare(pos_, std::strlen(s), s) == 0; }

  void step()
  {
    if(bytes_[pos_] == '\n')
      ++line_;
    ++pos_;
  }

  bool advance_to(char c)
  {
    const std::size_t found = bytes_.find(c, pos_);
    const std::size_t end = found == std::string_view::npos ? bytes_.size() : found;
    line_ += static_cast<std::size_t>(std::count(bytes_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                 bytes_.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
    pos_ = end;
    return found != std::string_view::npos;
  }

  void skip_past(const char* end, std::size_t start_line, const char* what)
  {
    const std::size_t found = bytes_.find(end, pos_);
    if(found == std::string_view::npos)
      fail(start_line, std::string("truncated: ") + what + " is not closed");
    while(pos_ < found + std::strlen(end))
      step();
  }

  void skip_spaces()
  {
    while(pos_ < bytes_.size() && is_space(bytes_[pos_]))
      step();
  }

  std::string_view take_name()
  {
    const std::size_t begin = pos_;
    while(pos_ < bytes_.size() && !is_space(bytes_[pos_]) && std::strchr("/>=<\"'", bytes_[pos_]) == nullptr)
      ++pos_;
    return bytes_.substr(begin, pos_ - begin);
  }

  static std::string decoded(std::string_view raw)
  {
    static const char* const entities[][2] = {{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}, {"&quot;", "\""},
                                              {"&apos;", "'"}};
    std::string out;
    for(std::size_t i = 0; i < raw.size();) {
      bool replaced = false;
      for(const auto& e : entities)
        if(raw.compare(i, std::strlen(e[0]), e[0]) == 0) {
          out += e[1];
          i += std::strlen(e[0]);
          replaced = true;
          break;
        }
      if(!replaced)
        out += raw[i++];
    }
    return out;
  }

  bool read_tag(XML_tag& tag)
  {
    tag = XML_tag();
    tag.line = line_;
    ++pos_;   // '<'
    if(pos_ < bytes_.size() && bytes_[pos_] == '/') {
      tag.closing = true;
      ++pos_;
    }
    tag.name = std::string(take_name());
    if(tag.name.empty())
      fail(tag.line, "a '<' that starts no tag");
    for(;;) {
      skip_spaces();
      if(pos_ == bytes_.size())
        fail(tag.line, "truncated: the tag <" + tag.name + " is not closed");
      if(bytes_[pos_] == '>') {
        ++pos_;
        return true;
      }
      if(bytes_.compare(pos_, 2, "/>") == 0 && !tag.closing) {
        tag.self_closing = true;
        pos_ += 2;
        return true;
      }
      const std::size_t at = line_;
      const std::string_view key = take_name();
      skip_spaces();
      if(key.empty() || tag.closing || pos_ == bytes_.size() || bytes_[pos_] != '=')
        fail(at, "malformed attribute in the tag <" + tag.name + ">");
      ++pos_;
      skip_spaces();
      if(pos_ == bytes_.size() || (bytes_[pos_] != '"' && bytes_[pos_] != '\''))
        fail(at, "the value of the attribute " + std::string(key) + " of <" + tag.name + "> is not quoted");
      const char quote = bytes_[pos_];
      const std::size_t end = bytes_.find(quote, pos_ + 1);
      if(end == std::string_view::npos)
        fail(at, "truncated: the value of the attribute " + std::string(key) + " of <" + tag.name + "> is not closed");
      tag.attributes.emplace_back(std::string(key), decoded(bytes_.substr(pos_ + 1, end - pos_ - 1)));
      while(pos_ <= end)
        step();
    }
  }

  std::string path_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_VTU_XML_H
