// A reader of text mesh files (OFF, OBJ, ASCII STL) line by line, with numbers parsed strictly.
//
// In:  the whole file as a string and its path (for messages).
// Out: non-empty lines with '#' comments removed, split into tokens, each line with its 1-based
//      number; `fail` throws InputError as "path:line: message", the form editors jump to.
#pragma once

#include <charconv>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.h"

namespace meromorph {

class TextLines {
public:
  // A UTF-8 byte-order mark at the start is skipped; lines may end in LF or CRLF, and the last
  // one needs no line end.
  TextLines(const std::string &path, const std::string &text) : path_(path), text_(text) {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) position_ = 3;
  }

  // Advances to the next line with at least one token; false at the end of the file.
  bool next() {
    while (position_ < text_.size()) {
      size_t end = text_.find('\n', position_);
      if (end == std::string::npos) end = text_.size();
      std::string_view line(text_.data() + position_, end - position_);
      position_ = end + 1;
      ++line_number_;
      const size_t comment = line.find('#');
      if (comment != std::string_view::npos) line = line.substr(0, comment);
      split(line);
      if (!tokens_.empty()) return true;
    }
    tokens_.clear();
    return false;
  }

  const std::vector<std::string_view> &tokens() const { return tokens_; }

  // True when the current line is the file's last and has no newline: complete, or cut short.
  bool cut_short() const {
    return position_ > text_.size() && !text_.empty() && text_.back() != '\n';
  }
  size_t line_number() const { return line_number_; }

  [[noreturn]] void fail(const std::string &message) const {
    throw InputError(path_ + ":" + std::to_string(line_number_) + ": " + message);
  }
  [[noreturn]] void fail_at_end(const std::string &message) const {
    throw InputError(path_ + ": " + message);
  }

  double number(size_t token) const {
    if (token >= tokens_.size()) fail("expected a number after '" + joined() + "'");
    double value = 0;
    std::string_view text = tokens_[token];
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      fail("'" + std::string(tokens_[token]) + "' is not a number");
    return value;
  }

  long integer(std::string_view text) const {
    long value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      fail("'" + std::string(text) + "' is not a whole number");
    return value;
  }
  long integer(size_t token) const {
    if (token >= tokens_.size()) fail("expected a whole number after '" + joined() + "'");
    return integer(tokens_[token]);
  }

private:
  void split(std::string_view line) {
    tokens_.clear();
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_space(line[i]))
        ++i;
      size_t start = i;
      while (i < line.size() && !is_space(line[i]))
        ++i;
      if (i > start) tokens_.push_back(line.substr(start, i - start));
    }
  }
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
  }
  std::string joined() const {
    std::string all;
    for (auto t : tokens_)
      all += (all.empty() ? "" : " ") + std::string(t);
    return all;
  }

  const std::string &path_;
  const std::string &text_;
  size_t position_ = 0;
  size_t line_number_ = 0;
  std::vector<std::string_view> tokens_;
};

} // namespace meromorph
