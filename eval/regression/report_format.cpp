#include "eval/regression/report_format.h"

#include <cstdint>

#include "core/error.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = unsigned(uint8_t(bytes[i])) << 16 | unsigned(uint8_t(bytes[i + 1])) << 8 |
                       unsigned(uint8_t(bytes[i + 2]));
    out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], digits[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = unsigned(uint8_t(bytes[i])) << 16;
    out += {digits[v >> 18], digits[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = unsigned(uint8_t(bytes[i])) << 16 | unsigned(uint8_t(bytes[i + 1])) << 8;
    out += {digits[v >> 18], digits[(v >> 12) & 63], digits[(v >> 6) & 63], '='};
  }
  return out;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::ofstream open_output(const fs::path& file) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  std::ofstream out(file);
  if (!out) throw_input_error(file.string(), "cannot write file");
  return out;
}

std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // XML 1.0 allows no control characters but tab and newlines.
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') ? ' ' : c;
    }
  }
  return out;
}

std::string escape_markdown(std::string text) {
  for (size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2)
    text.replace(at, 1, "\\|");
  return text;
}

std::string html_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" +
         escape_xml(title) +
         "</title>\n<style>\n"
         "body{font-family:sans-serif;margin:1.5em;max-width:1300px;color:#222}\n"
         "table{border-collapse:collapse;margin:0.6em 0}\n"
         "th,td{border:1px solid #bbb;padding:3px 8px;font-size:14px}\n"
         "td.num{text-align:right;font-family:monospace}\n"
         ".pass{background:#d8f0d8}.fail{background:#f7c6c6;font-weight:bold}"
         ".improved{background:#cfe3fa}.warn{background:#fbe7b5}.none{background:#e6e6e6}\n"
         ".banner{padding:8px 12px;font-size:18px;display:inline-block}\n"
         "img{max-width:600px;margin:4px;border:1px solid #ddd;vertical-align:top}\n"
         ".meta{color:#555;font-size:13px}\n</style></head><body>\n";
}

std::string html_image(const fs::path& png, const std::string& alt) {
  if (png.empty() || !fs::exists(png)) return "";
  return "<img alt=\"" + escape_xml(alt) + "\" src=\"data:image/png;base64," +
         base64(read_bytes(png)) + "\">\n";
}

}  // namespace slamkit::regress
