// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_TEXT_FILE_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_TEXT_FILE_H

#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/file_type.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

struct Token
{
  std::string_view text;
  std::size_t line = 0;
};

// Checked before opening: opening a FIFO without a writer would block.
inline void check_regular_input(const std::string& path)
{
  std::error_code ec;
  const std::filesystem::file_type type = std::filesystem::status(path, ec).type();
  if(type == std::filesystem::file_type::not_found)
    throw Read_error(path, 0, "file not found");
  if(is_special_file(type))
    throw Read_error(path, 0, "is " + special_file_name(type) + ", not a regular file");
}

/// Runs a reader, turning a failed allocation (a file too large for the
/// memory, or a memory cap) into a Read_error that names the file.
template <class Reader>
auto read_or_report_memory(const std::string& path, Reader read) -> decltype(read())
{
  try {
    return read();
  } catch(const std::bad_alloc&) {
    throw Read_error(path, 0, "out of memory while reading it");
  }
}

inline std::string read_whole_file(const std::string& path)
{
  check_regular_input(path);
  std::error_code ec;
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Read_error(path, 0, "cannot open file: " + std::generic_category().message(errno));
  std::string text;
  std::uintmax_t size = std::filesystem::file_size(path, ec);
  if(!ec)
    text.reserve(static_cast<std::size_t>(size));
  std::vector<char> buffer(1 << 16);
  while(in.read(buffer.data(), static_cast<std::streamsize>(buffer.size())) || in.gcount() > 0)
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
  if(in.bad())
    throw Read_error(path, 0, "cannot read file");
  return text;
}

// The whole file is held in memory so that tokens are cheap views and every
// error can name its line; the mesh itself is larger than its text anyway.
// Supports both token-stream formats (VTK, MEDIT) and line-structured ones
// (OFF, OBJ, .input), where a row must not spill over to the next line.
class Text_file
{
public:
  /// `comment` starts a comment running to the end of the line ('\0': none).
  explicit Text_file(const std::string& path, char comment = '\0')
    : path_(path), text_(read_whole_file(path)), comment_(comment)
  {
    // Editors on Windows may prepend a UTF-8 byte order mark.
    if(text_.compare(0, 3, "\xEF\xBB\xBF") == 0)
      pos_ = 3;
    std::size_t line = 1;
    for(char c : text_) {
      if(c == '\n')
        ++line;
      else if(!is_blank(c))
        last_line_ = line;
    }
  }

  const std::string& path() const { return path_; }

  /// The line a truncation error should point at: the last one with text.
  std::size_t last_line() const { return last_line_; }

  /// The next token, whatever line it is on; false at the end of the file.
  bool next_token(Token& token)
  {
    for(;;) {
      skip_blanks_on_line();
      if(pos_ == text_.size())
        return false;
      if(text_[pos_] != '\n')
        break;
      ++pos_;
      ++line_;
    }
    token = Token{take_word(), line_};
    return true;
  }

  /// The tokens of the next line that has any, at most `max_kept` of them:
  /// the others are only counted (tokens_on_line()), so that a run-away line
  /// costs no memory. False at the end of the file.
  bool next_line(std::vector<Token>& tokens, std::size_t max_kept = 9)
  {
    tokens.clear();
    tokens_on_line_ = 0;
    while(tokens_on_line_ == 0) {
      if(pos_ == text_.size())
        return false;
      read_rest_of_line(tokens, max_kept);
    }
    return true;
  }

  /// How many tokens the line last read by next_line() has, kept or not.
  std::size_t tokens_on_line() const { return tokens_on_line_; }

  /// The rest of the current line, verbatim (free-text lines such as a VTK
  /// title, which may even be empty); false at the end of the file.
  bool next_raw_line(std::string_view& text, std::size_t& line)
  {
    if(pos_ == text_.size())
      return false;
    std::size_t end = text_.find('\n', pos_);
    if(end == std::string::npos)
      end = text_.size();
    text = std::string_view(text_).substr(pos_, end - pos_);
    if(!text.empty() && text.back() == '\r')
      text.remove_suffix(1);
    line = line_;
    pos_ = end;
    if(pos_ < text_.size()) {
      ++pos_;
      ++line_;
    }
    return true;
  }

  /// The next word, past blanks and line ends, without taking it (empty at
  /// the end of the file): a reader's look ahead at the next section.
  std::string_view peek_word() const
  {
    std::size_t at = pos_;
    while(at < text_.size() && (is_blank(text_[at]) || text_[at] == '\n'))
      ++at;
    std::size_t end = at;
    while(end < text_.size() && !is_blank(text_[end]) && text_[end] != '\n')
      ++end;
    return std::string_view(text_).substr(at, end - at);
  }

  /// The byte offset of what comes next, for errors in binary data.
  std::size_t offset() const { return pos_; }

  /// How many bytes are left.
  std::size_t remaining() const { return text_.size() - pos_; }

  /// Ends the line before a block of binary data (a binary legacy VTK file),
  /// which starts after its '\n': false if other text is left on the line.
  bool end_line_before_data()
  {
    skip_blanks_on_line();
    if(pos_ == text_.size())
      return true;
    if(text_[pos_] != '\n')
      return false;
    ++pos_;
    ++line_;
    return true;
  }

  /// The next `n` bytes, whatever they are; false if fewer are left.  Their
  /// '\n' are counted, so that the lines after the block are the editor's.
  bool take_bytes(std::size_t n, std::string_view& bytes)
  {
    if(n > remaining())
      return false;
    bytes = std::string_view(text_).substr(pos_, n);
    for(char c : bytes)
      line_ += c == '\n' ? 1 : 0;
    pos_ += n;
    return true;
  }

  /// Upper bound on how many more items the file can hold, for reserve():
  /// a huge count in a small file must fail as truncated, not exhaust memory.
  std::size_t sane_capacity(std::size_t count) const
  {
    std::size_t remaining = text_.size() - pos_;
    return count < remaining / 2 + 1 ? count : remaining / 2 + 1;
  }

  [[noreturn]] void fail(std::size_t line, const std::string& reason) const
  {
    throw Read_error(path_, line, reason);
  }

  [[noreturn]] void fail_truncated(const std::string& what) const
  {
    fail(last_line_, "truncated: " + what);
  }

private:
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  // Leaves pos_ on the '\n' ending the line, or at the end of the text.
  void skip_blanks_on_line()
  {
    while(pos_ < text_.size()) {
      char c = text_[pos_];
      if(comment_ != '\0' && c == comment_) {
        std::size_t end = text_.find('\n', pos_);
        pos_ = (end == std::string::npos) ? text_.size() : end;
        return;
      }
      if(!is_blank(c))
        return;
      ++pos_;
    }
  }

  std::string_view take_word()
  {
    std::size_t begin = pos_;
    while(pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n'
          && !(comment_ != '\0' && text_[pos_] == comment_))
      ++pos_;
    return std::string_view(text_).substr(begin, pos_ - begin);
  }

  void read_rest_of_line(std::vector<Token>& tokens, std::size_t max_kept)
  {
    for(;;) {
      skip_blanks_on_line();
      if(pos_ == text_.size())
        return;
      if(text_[pos_] == '\n') {
        ++pos_;
        ++line_;
        return;
      }
      const Token token{take_word(), line_};
      if(tokens_on_line_++ < max_kept)
        tokens.push_back(token);
    }
  }

  std::string path_;
  std::string text_;
  char comment_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t last_line_ = 1;
  std::size_t tokens_on_line_ = 0;
};

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_TEXT_FILE_H
