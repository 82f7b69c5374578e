#pragma once
// The pieces every slamkit report is written with (the regression report, the sweep report):
// escaping for Markdown and HTML, one page style, PNG plots embedded so that report.html is
// viewed without the run folders or a network.
#include <filesystem>
#include <fstream>
#include <string>

namespace slamkit::regress {

// Creates the folder; InputError naming the file when it cannot be written.
std::ofstream open_output(const std::filesystem::path& file);

std::string escape_xml(const std::string& text);
std::string escape_markdown(std::string text);  // table cells: '|' escaped

// <!DOCTYPE ...> through <body>, with the reports' style sheet (classes pass, fail, improved,
// warn, none, banner, meta, num).
std::string html_head(const std::string& title);
// An <img> with the PNG inline (base64), or "" when the file does not exist.
std::string html_image(const std::filesystem::path& png, const std::string& alt);

}  // namespace slamkit::regress
