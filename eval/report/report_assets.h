#pragma once
// Files compiled into the binary (eval/CMakeLists.txt, cmake/embed_text_files.cmake): the report
// page's template, style and script, and three.js r111 with its OrbitControls from Debian's
// libjs-three, inlined into every page so that it opens with no network.
#include <string_view>

namespace slamkit::eval::report_assets {

extern const std::string_view three_js;           // three.min.js
extern const std::string_view orbit_controls_js;  // examples/js/controls/OrbitControls.js
extern const std::string_view page_html;          // eval/report/assets/report.html
extern const std::string_view page_css;           // eval/report/assets/report.css
extern const std::string_view page_js;            // eval/report/assets/report.js

}  // namespace slamkit::eval::report_assets
