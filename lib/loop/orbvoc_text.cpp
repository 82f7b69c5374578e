// DBoW2's text vocabulary format (ORB-SLAM2's ORBvoc.txt), read from its description in
// vocabulary_file.h.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "loop/vocabulary_file.h"

namespace slamkit {
namespace {

// Parses the whitespace-separated numbers of one line in order; any failure names the line.
class LineParser {
 public:
  LineParser(const std::string& text, const std::string& path, int line)
      : cursor_(text.c_str()), path_(path), line_(line) {}
  long integer(const char* what, long lo, long hi) {
    char* end;
    errno = 0;
    const long v = std::strtol(cursor_, &end, 10);
    if (end == cursor_ || errno != 0 || v < lo || v > hi)
      fail(std::string("expected ") + what + " (" + std::to_string(lo) + ".." +
           std::to_string(hi) + ")");
    cursor_ = end;
    return v;
  }
  double real(const char* what) {
    char* end;
    const double v = std::strtod(cursor_, &end);
    if (end == cursor_ || !std::isfinite(v)) fail(std::string("expected ") + what);
    cursor_ = end;
    return v;
  }
  void finish() {
    while (*cursor_ == ' ' || *cursor_ == '\t' || *cursor_ == '\r') ++cursor_;
    if (*cursor_ != '\0') fail("unexpected text after the last value");
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw_input_error(path_, line_, message);
  }

 private:
  const char* cursor_;
  const std::string& path_;
  int line_;
};

}  // namespace

Vocabulary read_orbvoc_text(const std::filesystem::path& file) {
  const std::string path = file.string();
  std::ifstream in(file);
  if (!in) throw_input_error(path, "cannot open vocabulary file");
  std::string text;
  if (!std::getline(in, text)) throw_input_error(path, 1, "empty vocabulary file");
  LineParser header(text, path, 1);
  const int branching = int(header.integer("k", 2, 1000));
  const int depth = int(header.integer("L", 1, 100));
  const long scoring = header.integer("scoring", 0, 5);
  const long weighting = header.integer("weighting", 0, 3);
  header.finish();
  if (scoring != 0 || weighting != 0)
    header.fail("only L1-norm scoring with TF-IDF weighting (0 0) is supported");

  std::vector<VocabularyNode> nodes(1);
  std::vector<bool> leaf(1, false);
  std::vector<int> line_of(1, 1);
  for (int line = 2; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    LineParser p(text, path, line);
    VocabularyNode node;
    const long parent = p.integer("parent id", 0, long(nodes.size()) - 1);
    const bool is_leaf = p.integer("is_leaf", 0, 1) == 1;
    for (uint8_t& byte : node.descriptor) byte = uint8_t(p.integer("descriptor byte", 0, 255));
    node.weight = p.real("weight");
    p.finish();
    if (leaf[parent]) p.fail("parent " + std::to_string(parent) + " is marked as a leaf");
    node.parent = NodeId(parent);
    nodes.push_back(node);
    leaf.push_back(is_leaf);
    line_of.push_back(line);
  }
  // Words are the leaves in node order, as DBoW2 numbers them: an inner node must have
  // children, or our numbering would differ from the file's.
  std::vector<bool> has_child(nodes.size(), false);
  for (size_t i = 1; i < nodes.size(); ++i) has_child[nodes[i].parent] = true;
  for (size_t i = 1; i < nodes.size(); ++i)
    if (!leaf[i] && !has_child[i])
      throw_input_error(path, line_of[i], "node marked inner has no children");

  std::vector<double> weights;
  for (size_t i = 1; i < nodes.size(); ++i)
    if (leaf[i]) weights.push_back(nodes[i].weight);
  Vocabulary vocabulary(branching, depth, std::move(nodes));
  vocabulary.set_weights(weights);
  return vocabulary;
}

}  // namespace slamkit
