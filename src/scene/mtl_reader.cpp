#include "scene/mtl_reader.hpp"

#include <cmath>
#include <map>
#include <set>

#include "scene/number.hpp"

namespace clrt {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

struct MtlWord {
  std::string_view text;
  int column;  // 1-based
};

// One statement: its words up to a word starting with '#', and the line they came from.
struct Statement {
  std::string_view line;
  int number;
  std::vector<MtlWord> words;
};

Statement split(std::string_view line, int number) {
  Statement s{line, number, {}};
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i == line.size() || line[i] == '#') break;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    s.words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return s;
}

// At most 40 bytes of a word, so that a huge one is not echoed whole.
std::string excerpt(std::string_view word) {
  return "'" + std::string(word.substr(0, 40)) + (word.size() > 40 ? "...'" : "'");
}

class Reader {
 public:
  Reader(const Statement& s, const std::string& file) : s_(s), file_(file) {}

  std::size_t count() const { return s_.words.size() - 1; }  // words after the keyword
  const MtlWord& word(std::size_t i) const { return s_.words[i + 1]; }
  SourceLocation at(std::size_t i) const { return {file_, s_.number, word(i).column}; }
  // Just past the last word: where a missing one would go.
  SourceLocation past_end() const {
    const MtlWord& last = s_.words.back();
    return {file_, s_.number, last.column + static_cast<int>(last.text.size())};
  }
  [[noreturn]] void fail_at(std::size_t i, const std::string& message) const { throw SceneError(at(i), message); }
  [[noreturn]] void fail_past_end(const std::string& message) const { throw SceneError(past_end(), message); }

  double number(std::size_t i, double low, double high, const char* what) const {
    if (i >= count()) fail_past_end(std::string("missing ") + what);
    const ParsedNumber n = parse_number(word(i).text);
    if (n.problem != NumberProblem::None) fail_at(i, excerpt(word(i).text) + " is not a usable number for " + what);
    if (!(n.value >= low && n.value <= high))
      fail_at(i, what + std::string(" must be in [") + std::to_string(low) + ", " + std::to_string(high) +
                     "], found " + excerpt(word(i).text));
    return n.value;
  }

  void require_count(std::size_t most) const {
    if (count() > most) fail_at(most, "unexpected " + excerpt(word(most).text) + " after " + keyword());
  }

  // The text from word i to the end of the last word: a name or a path, which may hold spaces.
  std::string rest(std::size_t i) const {
    const MtlWord& first = word(i);
    const MtlWord& last = s_.words.back();
    return std::string(s_.line.substr(static_cast<std::size_t>(first.column - 1),
                                      static_cast<std::size_t>(last.column - first.column) + last.text.size()));
  }

  std::string keyword() const { return std::string(s_.words.front().text); }

 private:
  const Statement& s_;
  const std::string& file_;
};

// `Kd r g b` or `Kd r` (grey).
Vec3 colour(const Reader& r) {
  const char* what = "a colour channel (>= 0)";
  const double red = r.number(0, 0, 1e12, what);
  if (r.count() == 1) return {red, red, red};
  r.require_count(3);
  return {red, r.number(1, 0, 1e12, what), r.number(2, 0, 1e12, what)};
}

// How many values each map option takes, at most (the first ones required).
struct MapOption {
  int least, most;
  bool rendered;
};
const std::map<std::string, MapOption>& map_options() {
  static const std::map<std::string, MapOption> options = {
      {"-clamp", {1, 1, true}}, {"-s", {1, 3, true}},      {"-o", {1, 3, true}},     {"-bm", {1, 1, true}},
      {"-blendu", {1, 1, false}}, {"-blendv", {1, 1, false}}, {"-cc", {1, 1, false}}, {"-mm", {2, 2, false}},
      {"-t", {1, 3, false}},      {"-texres", {1, 1, false}}, {"-imfchan", {1, 1, false}}, {"-boost", {1, 1, false}},
      {"-type", {1, 1, false}}};
  return options;
}

class Parser {
 public:
  explicit Parser(const std::string& file) : file_(file) {}

  void statement(const Statement& s) {
    if (s.words.empty()) return;
    const Reader r(s, file_);
    const std::string keyword = r.keyword();
    if (keyword == "newmtl") {
      if (r.count() == 0) r.fail_past_end("newmtl needs a material name");
      MtlMaterial m;
      m.name = r.rest(0);
      m.where = r.at(0);
      out_.materials.push_back(std::move(m));
      return;
    }
    if (out_.materials.empty()) throw SceneError({file_, s.number, s.words.front().column},
                                                 excerpt(keyword) + " before the first newmtl");
    MtlMaterial& m = out_.materials.back();
    if (keyword == "Kd" || keyword == "Ks" || keyword == "Ke") {
      if (r.count() > 0 && (r.word(0).text == "spectral" || r.word(0).text == "xyz"))
        return warn(r, keyword + " " + std::string(r.word(0).text), r.word(0).column);
      (keyword == "Kd" ? m.kd : keyword == "Ks" ? m.ks : m.ke) = colour(r);
    } else if (keyword == "Ns") {
      r.require_count(1);
      m.ns = r.number(0, 0, 1e12, "Ns (>= 0)");
    } else if (keyword == "Ni") {
      r.require_count(1);
      m.ni = r.number(0, 1e-6, 1e12, "Ni (> 0)");
    } else if (keyword == "d" || keyword == "Tr") {
      if (r.count() > 0 && r.word(0).text == "-halo") return warn(r, keyword + " -halo", r.word(0).column);
      r.require_count(1);
      const double v = r.number(0, 0, 1, keyword == "d" ? "d" : "Tr");
      m.dissolve = keyword == "d" ? v : 1 - v;
    } else if (keyword == "illum") {
      r.require_count(1);
      const double v = r.number(0, 0, 10, "illum (0 to 10)");
      if (v != std::floor(v)) r.fail_at(0, "illum is a whole number, found " + excerpt(r.word(0).text));
      m.illum = static_cast<int>(v);
    } else if (keyword == "map_Kd" || keyword == "map_Ks" || keyword == "map_bump" || keyword == "bump") {
      (keyword == "map_Kd" ? m.map_kd : keyword == "map_Ks" ? m.map_ks : m.map_bump) = map(r);
    } else {
      warn(r, keyword, s.words.front().column);
    }
  }

  MtlLibrary take() { return std::move(out_); }

 private:
  MtlTextureRef map(const Reader& r) {
    MtlTextureRef t;
    std::size_t i = 0;
    while (i < r.count() && r.word(i).text.size() > 1 && r.word(i).text[0] == '-') {
      const std::string option(r.word(i).text);
      const auto found = map_options().find(option);
      if (found == map_options().end()) r.fail_at(i, "unknown option " + excerpt(option) + " of " + r.keyword());
      const MapOption o = found->second;
      if (option == "-bm" && r.keyword() != "map_bump" && r.keyword() != "bump")
        r.fail_at(i, "-bm belongs to bump maps, not " + r.keyword());
      if (!o.rendered) warn(r, r.keyword() + " " + option, r.word(i).column);
      const std::size_t first = ++i;
      std::vector<double> values;
      // Values run until the next option, the file name or the most the option takes.
      while (i < r.count() && static_cast<int>(values.size()) < o.most && i + 1 < r.count() &&
             r.word(i).text[0] != '-') {
        if (option == "-clamp" || option == "-blendu" || option == "-blendv" || option == "-cc" ||
            option == "-imfchan" || option == "-type") {
          const std::string_view v = r.word(i).text;
          if (option != "-imfchan" && option != "-type" && v != "on" && v != "off")
            r.fail_at(i, option + " takes on or off, found " + excerpt(v));
          if (option == "-clamp") t.clamp = v == "on";
          values.push_back(0);
          ++i;
          continue;
        }
        const ParsedNumber n = parse_number(r.word(i).text);
        if (n.problem != NumberProblem::None) break;  // the file name
        values.push_back(n.value);
        ++i;
      }
      // Short of values with at most one word left: that word is the option's or the file's, and
      // either way a word is missing.
      if (static_cast<int>(values.size()) < o.least && i + 1 >= r.count())
        r.fail_past_end(r.keyword() + " needs a file name after its options");
      if (static_cast<int>(values.size()) < o.least)
        r.fail_at(first, option + " needs " + std::to_string(o.least) + " value(s)");
      if (option == "-s" || option == "-o") {
        Vec3& v = option == "-s" ? t.scale : t.offset;
        v.x = values[0];
        if (values.size() > 1) v.y = values[1];
        if (values.size() > 2) v.z = values[2];
      }
      if (option == "-bm") t.bump_multiplier = values[0];
    }
    if (i >= r.count()) r.fail_past_end(r.keyword() + " needs a file name");
    t.path = r.rest(i);
    t.where = r.at(i);
    return t;
  }

  // Once per `what` (a keyword, or a keyword and its option), at its first place.
  void warn(const Reader& r, const std::string& what, int column) {
    if (!warned_.insert(what).second) return;
    out_.warnings.push_back(
        scene_warning({file_, r.past_end().line, column}, "'" + what + "' is not rendered by clrt; ignored"));
  }

  const std::string& file_;
  MtlLibrary out_;
  std::set<std::string> warned_;
};

}  // namespace

MtlLibrary parse_mtl(std::string_view text, const std::string& file) {
  Parser parser(file);
  int number = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    parser.statement(split(text.substr(0, end), ++number));
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return parser.take();
}

}  // namespace clrt
