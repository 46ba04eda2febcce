#include "lvslam/report/json_value.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::report {

namespace {

// Recursive descent over the text; depth is bounded so a hostile file cannot
// overflow the stack.
class Parser {
 public:
  Parser(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  JsonValue document() {
    JsonValue value = parseValue(0);
    skipSpace();
    if (pos_ != text_.size()) fail("unexpected text after the end of the document");
    return value;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    const std::string what = pos_ >= text_.size() ? "the file ends early (truncated?): " + why : why;
    throw Error(name_, fmt::format("invalid JSON at byte {}: {}", pos_, what));
  }

  void skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\r' || text_[pos_] == '\t'))
      ++pos_;
  }

  void expect(char c) {
    skipSpace();
    if (pos_ >= text_.size() || text_[pos_] != c) fail(fmt::format("expected '{}'", c));
    ++pos_;
  }

  bool consume(char c) {
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  JsonValue parseValue(int depth) {
    if (depth > 64) fail("nested too deeply");
    skipSpace();
    if (pos_ >= text_.size()) fail("expected a value");
    const char c = text_[pos_];
    if (c == '{') return parseObject(depth);
    if (c == '[') return parseArray(depth);
    JsonValue v;
    if (c == '"') {
      v.type = JsonValue::Type::kString;
      v.string = parseString();
    } else if (literal("true") || literal("false")) {
      v.type = JsonValue::Type::kBool;
      v.boolean = c == 't';
    } else if (literal("null")) {
      v.type = JsonValue::Type::kNull;
    } else {
      v.type = JsonValue::Type::kNumber;
      v.number = parseNumber();
    }
    return v;
  }

  bool literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }

  double parseNumber() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && std::string_view("+-0123456789.eE").find(text_[pos_]) != std::string_view::npos) ++pos_;
    const std::string digits(text_.substr(start, pos_ - start));
    char* end = nullptr;
    const double value = std::strtod(digits.c_str(), &end);
    if (digits.empty() || end != digits.c_str() + digits.size()) {
      pos_ = start;
      fail("expected a value");
    }
    return value;
  }

  std::string parseString() {
    ++pos_;  // the opening quote
    std::string out;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      char c = text_[pos_++];
      if (c == '\\') {
        if (pos_ >= text_.size()) break;
        const char e = text_[pos_++];
        if (e == 'u') {
          if (pos_ + 4 > text_.size()) break;
          const unsigned code = std::stoul(std::string(text_.substr(pos_, 4)), nullptr, 16);
          pos_ += 4;
          out += code < 0x80 ? static_cast<char>(code) : '?';  // lvslam writes ASCII; enough for names
          continue;
        }
        c = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e;
      }
      out += c;
    }
    if (pos_ >= text_.size()) fail("unterminated string");
    ++pos_;  // the closing quote
    return out;
  }

  JsonValue parseArray(int depth) {
    ++pos_;
    JsonValue v;
    v.type = JsonValue::Type::kArray;
    if (consume(']')) return v;
    do v.array.push_back(parseValue(depth + 1));
    while (consume(','));
    expect(']');
    return v;
  }

  JsonValue parseObject(int depth) {
    ++pos_;
    JsonValue v;
    v.type = JsonValue::Type::kObject;
    if (consume('}')) return v;
    do {
      skipSpace();
      if (pos_ >= text_.size() || text_[pos_] != '"') fail("expected a key in quotes");
      std::string key = parseString();
      expect(':');
      v.object[std::move(key)] = parseValue(depth + 1);
    } while (consume(','));
    expect('}');
    return v;
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

}  // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
  if (type != Type::kObject) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &it->second;
}

JsonValue parseJson(std::string_view text, const std::string& name) { return Parser(text, name).document(); }

JsonValue readJsonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot read the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parseJson(buffer.str(), path);
}

}  // namespace lvslam::report
