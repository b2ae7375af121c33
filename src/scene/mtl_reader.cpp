#include "scene/mtl_reader.hpp"

#include <algorithm>
#include <climits>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "scene/limits.hpp"
#include "scene/number.hpp"
#include "scene/texture_rules.hpp"
#include "text/nearest_name.hpp"

namespace clrt {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Lines and columns are ints in a SourceLocation; a place beyond (in a line over 2 GiB) shows as
// the last one.
int capped(std::size_t n) { return static_cast<int>(std::min<std::size_t>(n, INT_MAX)); }

std::string quoted(std::string_view word) { return "'" + excerpt(word) + "'"; }

struct Word {
  std::string_view text;
  std::size_t begin;  // offset in its line
  std::size_t end() const { return begin + text.size(); }
};

// The end of the last word of `line`, or 0 for none: a word starting with '#' begins a comment.
std::size_t statement_end(std::string_view line) {
  std::size_t end = 0;
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i == line.size() || line[i] == '#') return end;
    while (i < line.size() && !is_blank(line[i])) ++i;
    end = i;
  }
}

// One line's statement, taken word by word. Nothing is copied, so a huge line costs no memory.
class Statement {
 public:
  Statement(std::string_view line, int number, const std::string& file)
      : line_(line), number_(number), file_(file), end_(statement_end(line)), next_(skip_blanks(0)) {}

  bool more() const { return next_ < end_; }
  // The next word; only while more().
  Word peek() const {
    std::size_t e = next_;
    while (e < end_ && !is_blank(line_[e])) ++e;
    return {line_.substr(next_, e - next_), next_};
  }
  Word take() {
    const Word w = peek();
    next_ = skip_blanks(w.end());
    return w;
  }
  bool is_last(const Word& w) const { return w.end() == end_; }
  // From the next word to the end of the last: a name or a path, which may hold spaces.
  std::string_view rest() const { return line_.substr(next_, end_ - next_); }
  // The MTL format joins a line ending in '\' with the next one.
  bool continues() const { return end_ > 0 && line_[end_ - 1] == '\\'; }

  SourceLocation at(const Word& w) const { return at_offset(w.begin); }
  // Just past the last word: where a missing one would go.
  SourceLocation past_end() const { return at_offset(end_); }
  SourceLocation last_byte() const { return at_offset(end_ - 1); }
  [[noreturn]] void fail_at(const Word& w, const std::string& message) const { throw SceneError(at(w), message); }
  [[noreturn]] void fail_past_end(const std::string& message) const { throw SceneError(past_end(), message); }

 private:
  std::size_t skip_blanks(std::size_t i) const {
    while (i < end_ && is_blank(line_[i])) ++i;
    return i;
  }
  SourceLocation at_offset(std::size_t offset) const { return {file_, number_, capped(offset + 1)}; }

  std::string_view line_;
  int number_;
  const std::string& file_;
  std::size_t end_;
  std::size_t next_;
};

// The words that may follow a value-taking map option without being read as the file name.
bool looks_numeric(const Word& w) { return parse_number(w.text).problem != NumberProblem::NotANumber; }

// Word `w` as a finite number within the scene limits, for `what` (named in messages).
double finite_number(const Statement& s, const Word& w, const std::string& what) {
  const ParsedNumber n = parse_number(w.text);
  switch (n.problem) {
    case NumberProblem::None:
      return n.value;
    case NumberProblem::NotANumber:
      s.fail_at(w, what + ": expected a number, found " + quoted(w.text));
    case NumberProblem::NotFinite:
      s.fail_at(w, what + ": " + quoted(w.text) + " is not a finite number");
    case NumberProblem::OutOfRange:
      s.fail_at(w, what + ": " + quoted(w.text) + " is out of the range of a double");
    case NumberProblem::TooLarge:
      break;
  }
  s.fail_at(w, what + ": " + quoted(w.text) + " is too large: numbers lie within -" +
                   short_number(limits::kMaxNumber) + " and " + short_number(limits::kMaxNumber));
}

struct Range {
  double low, high;
  bool above_low = false;  // low itself is out, as 0 is for Ni

  bool holds(double v) const { return (above_low ? v > low : v >= low) && v <= high; }
  std::string text() const {
    return (above_low ? "(" : "[") + short_number(low) + ", " + short_number(high) + "]";
  }
};

// The next word as a number for statement `what`, within `range`.
double number(Statement& s, const std::string& what, const Range& range) {
  if (!s.more()) s.fail_past_end(what + ": a number is missing");
  const Word w = s.take();
  const double v = finite_number(s, w, what);
  if (!range.holds(v)) s.fail_at(w, what + " must be in " + range.text() + ", found " + quoted(w.text));
  return v;
}

void finish(const Statement& s, std::string_view keyword) {
  if (s.more()) s.fail_at(s.peek(), "unexpected " + quoted(s.peek().text) + " after " + std::string(keyword));
}

// A colour channel, and Ns: no upper bound but the scene limit on every number.
constexpr Range kAtLeastZero{0, limits::kMaxNumber};

// Statement `Ns`, `Ni`, `d` or `Tr`: one number.
double single(Statement& s, std::string_view keyword, const Range& range) {
  const double v = number(s, std::string(keyword), range);
  finish(s, keyword);
  return v;
}

int illum(Statement& s) {
  if (!s.more()) s.fail_past_end("illum: a number is missing");
  const Word w = s.peek();
  const double v = single(s, "illum", {0, 10});
  if (v != std::floor(v)) s.fail_at(w, "illum is a whole number, found " + quoted(w.text));
  return static_cast<int>(v);
}

enum class Takes { OnOff, Channel, Numbers };

struct MapOption {
  std::string_view name;
  Takes takes;
  int least, most;  // how many values (always 1 but for numbers)
  bool rendered;    // clrt keeps what it says; the others are a warning
};

constexpr MapOption kMapOptions[] = {
    {"-clamp", Takes::OnOff, 1, 1, true},     {"-s", Takes::Numbers, 1, 3, true},
    {"-o", Takes::Numbers, 1, 3, true},       {"-bm", Takes::Numbers, 1, 1, true},
    {"-blendu", Takes::OnOff, 1, 1, false},   {"-blendv", Takes::OnOff, 1, 1, false},
    {"-cc", Takes::OnOff, 1, 1, false},       {"-mm", Takes::Numbers, 2, 2, false},
    {"-t", Takes::Numbers, 1, 3, false},      {"-texres", Takes::Numbers, 1, 1, false},
    {"-imfchan", Takes::Channel, 1, 1, false}, {"-boost", Takes::Numbers, 1, 1, false},
};

const MapOption* map_option(std::string_view name) {
  for (const MapOption& o : kMapOptions)
    if (o.name == name) return &o;
  return nullptr;
}

// A file name may not start with '-' and hold more, so that a misspelt option is not taken
// for the file.
bool is_option(const Word& w) { return w.text.size() > 1 && w.text[0] == '-'; }

std::string values_text(const MapOption& o) {
  switch (o.takes) {
    case Takes::OnOff:
      return "on or off";
    case Takes::Channel:
      return "r, g, b, m, l or z";
    case Takes::Numbers:
      break;
  }
  const std::string least = std::to_string(o.least) + (o.least == 1 ? " value" : " values");
  return o.least == o.most ? least : least + ", up to " + std::to_string(o.most);
}

bool is_value(Takes takes, std::string_view word) {
  if (takes == Takes::OnOff) return word == "on" || word == "off";
  return word.size() == 1 && std::string_view("rgbmlz").find(word[0]) != std::string_view::npos;
}

// u [v [w]] over `defaults`.
Vec3 partial_vec3(const double* values, int count, const Vec3& defaults) {
  return {values[0], count > 1 ? values[1] : defaults.y, count > 2 ? values[2] : defaults.z};
}

// The keywords clrt reads, as the format spells them.
const std::vector<std::string> kReadKeywords = {"newmtl", "Kd",     "Ks",     "Ke",       "Ns",  "Ni", "d",
                                                "Tr",     "illum",  "map_Kd", "map_Ks", "map_bump", "bump"};
// Keywords exporters write that clrt does not render: each is the note "not rendered", never
// taken for a misspelling of one clrt reads (Ka is one letter from Kd).
const std::vector<std::string> kUnrenderedKeywords = {
    "Ka",     "Tf",    "Km",   "sharpness", "map_Ka", "map_d", "map_Ns", "map_Tr", "map_Ke", "map_Pr",
    "map_Pm", "map_Ps", "disp", "decal",     "refl",   "Pr",    "Pm",     "Ps",     "Pc",     "Pcr",
    "aniso",  "anisor", "norm"};

std::string lower(std::string_view word) {
  std::string out(word);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The keyword of `names` that `word` is in another case, or null.
const std::string* other_case_of(std::string_view word, const std::vector<std::string>& names) {
  const std::string lowered = lower(word);
  for (const std::string& name : names)
    if (lower(name) == lowered) return &name;
  return nullptr;
}

// "did you mean 'Kd'?" for the keyword nearest to `word` whatever their cases, or "".
std::string nearest_keyword(std::string_view word) {
  std::vector<std::string> names = kReadKeywords, lowered;
  names.insert(names.end(), kUnrenderedKeywords.begin(), kUnrenderedKeywords.end());
  for (const std::string& name : names) lowered.push_back(lower(name));
  const std::optional<std::string> near = nearest_name(lower(word), lowered);
  if (!near) return "";
  const auto at = std::find(lowered.begin(), lowered.end(), *near) - lowered.begin();
  return "did you mean '" + names[static_cast<std::size_t>(at)] + "'?";
}

class Parser {
 public:
  explicit Parser(const std::string& file) : file_(file) {}

  void statement(Statement& s) {
    if (!s.more()) return;
    if (s.continues())
      throw SceneError(s.last_byte(), "a line ending in '\\' continues on the next line, which clrt does not "
                                      "support: write the statement on one line");
    const Word keyword = s.take();
    // Keywords are case-sensitive in the format, but exporters differ: `map_kd` is read as
    // `map_Kd`, with a note, rather than lose the texture.
    std::string_view k = keyword.text;
    if (const std::string* known = other_case_of(k, kReadKeywords); known && *known != k) {
      warn_once(s.at(keyword), "case " + std::string(k),
                quoted(k) + " is read as '" + *known + "' (MTL keywords are case-sensitive)");
      k = *known;
    }
    if (k == "newmtl") return new_material(s);
    if (out_.materials.empty()) {
      const std::string near = other_case_of(k, kUnrenderedKeywords) ? "" : nearest_keyword(k);
      s.fail_at(keyword, quoted(k) + " before the first newmtl" + in_parentheses(near));
    }
    MtlMaterial& m = out_.materials.back();
    if (k == "Kd" || k == "Ks" || k == "Ke")
      colour(s, k, k == "Kd" ? m.kd : k == "Ks" ? m.ks : m.ke);
    else if (k == "Ns")
      m.ns = single(s, k, kAtLeastZero);
    else if (k == "Ni")
      m.ni = single(s, k, {0, limits::kMaxNumber, true});
    else if (k == "d" || k == "Tr")
      dissolve(s, k, m.dissolve);
    else if (k == "illum")
      m.illum = illum(s);
    else if (k == "map_Kd" || k == "map_Ks" || k == "map_bump" || k == "bump")
      (k == "map_Kd" ? m.map_kd : k == "map_Ks" ? m.map_ks : m.map_bump) = map(s, k);
    else
      unknown(s.at(keyword), k);
  }

  MtlLibrary take() { return std::move(out_); }

 private:
  void new_material(Statement& s) {
    if (!s.more()) s.fail_past_end("newmtl needs a material name");
    MtlMaterial m;
    m.where = s.at(s.peek());
    m.name = std::string(s.rest());
    const auto [first, fresh] = first_lines_.emplace(m.name, m.where.line);
    if (!fresh)
      out_.warnings.push_back(scene_warning(m.where, "material " + quoted(m.name) + " is defined again (first at line " +
                                                         std::to_string(first->second) +
                                                         "); this later definition counts"));
    out_.last_definition[m.name] = out_.materials.size();
    out_.materials.push_back(std::move(m));
  }

  // `Kd r g b`, or `Kd r` for grey.
  void colour(Statement& s, std::string_view keyword, std::optional<Vec3>& into) {
    const std::string what(keyword);
    if (s.more() && (s.peek().text == "spectral" || s.peek().text == "xyz")) {
      const Word form = s.take();
      return warn(s.at(form), what + " " + std::string(form.text));
    }
    const double r = number(s, what, kAtLeastZero);
    if (!s.more()) {
      into = Vec3{r, r, r};
      return;
    }
    const double g = number(s, what, kAtLeastZero);
    const double b = number(s, what, kAtLeastZero);
    finish(s, keyword);
    into = Vec3{r, g, b};
  }

  void dissolve(Statement& s, std::string_view keyword, std::optional<double>& into) {
    if (s.more() && s.peek().text == "-halo") {
      const Word halo = s.take();
      return warn(s.at(halo), std::string(keyword) + " -halo");
    }
    const double v = single(s, keyword, {0, 1});
    into = keyword == "d" ? v : 1 - v;
  }

  MtlTextureRef map(Statement& s, std::string_view keyword) {
    MtlTextureRef t;
    while (s.more() && is_option(s.peek())) option(s, keyword, t);
    if (!s.more()) s.fail_past_end(std::string(keyword) + " needs a file name");
    t.where = s.at(s.peek());
    t.path = std::string(s.rest());
    return t;
  }

  void option(Statement& s, std::string_view keyword, MtlTextureRef& t) {
    const Word name = s.take();
    const MapOption* o = map_option(name.text);
    const std::string map(keyword);
    if (!o) {
      std::vector<std::string> names;
      for (const MapOption& known : kMapOptions) names.emplace_back(known.name);
      const std::string near = did_you_mean(std::string(name.text), names);
      s.fail_at(name, "unknown option " + quoted(name.text) + " of " + map + in_parentheses(near));
    }
    if (o->name == "-bm" && keyword != "map_bump" && keyword != "bump")
      s.fail_at(name, "-bm belongs to bump maps, not " + map);
    if (!o->rendered) warn(s.at(name), map + " " + std::string(o->name));
    const std::string needs = std::string(o->name) + " needs " + values_text(*o);
    // The last word is the file name, so a value must leave one after it.
    const auto value_follows = [&s] { return s.more() && !s.is_last(s.peek()); };
    double values[3];
    int count = 0;
    while (count < o->most && value_follows() && (o->takes != Takes::Numbers || looks_numeric(s.peek()))) {
      const Word w = s.take();
      if (o->takes != Takes::Numbers && !is_value(o->takes, w.text)) {
        const std::string near = o->takes == Takes::OnOff ? did_you_mean(lower(w.text), {"on", "off"}) : "";
        s.fail_at(w, needs + ", found " + quoted(w.text) + in_parentheses(near));
      }
      values[count++] = o->takes == Takes::Numbers ? finite_number(s, w, map + " " + std::string(o->name)) : 0;
      // u and v are the texture's scale; a w is read, and a warning unless it changes nothing.
      if (o->name == "-s" && count <= 2)
        if (const auto problem = texture_scale_problem(values[count - 1])) s.fail_at(w, map + " -s: " + *problem);
      if ((o->name == "-s" || o->name == "-o") && count == 3 && values[2] != (o->name == "-s" ? 1 : 0))
        warn_once(s.at(w), map + " " + std::string(o->name) + " w",
                  map + " " + std::string(o->name) + ": clrt's textures have two coordinates, so its third value (w) "
                  "is not used; ignored");
      if (o->name == "-clamp") t.clamp = w.text == "on";
    }
    if (count < o->least && !value_follows())
      s.fail_past_end(map + " needs a file name after its options (" + needs + ")");
    if (count < o->least) s.fail_at(s.peek(), needs + ", found " + quoted(s.peek().text));
    if (o->name == "-s") t.scale = partial_vec3(values, count, MtlTextureRef{}.scale);
    if (o->name == "-o") t.offset = partial_vec3(values, count, MtlTextureRef{}.offset);
    if (o->name == "-bm") t.bump_multiplier = values[0];
  }

  // A keyword clrt does not read: one that exporters write is not rendered; one near a keyword
  // is probably that keyword misspelt, which would otherwise drop a colour or a texture unseen.
  void unknown(const SourceLocation& where, std::string_view k) {
    const std::string near = other_case_of(k, kUnrenderedKeywords) ? "" : nearest_keyword(k);
    if (near.empty()) return warn(where, std::string(k));
    warn_once(where, std::string(k), "unknown statement " + quoted(k) + " (" + near + "); ignored");
  }

  // Once per `what` (a keyword, or a keyword and its option), at its first place.
  void warn(const SourceLocation& where, const std::string& what) {
    warn_once(where, what, quoted(what) + " is not rendered by clrt; ignored");
  }
  void warn_once(const SourceLocation& where, const std::string& what, const std::string& message) {
    if (warned_.insert(what).second) out_.warnings.push_back(scene_warning(where, message));
  }

  const std::string& file_;
  MtlLibrary out_;
  std::set<std::string> warned_;
  std::map<std::string, int> first_lines_;  // of each material name
};

}  // namespace

const MtlMaterial* MtlLibrary::find(std::string_view name) const {
  const auto found = last_definition.find(std::string(name));
  return found == last_definition.end() ? nullptr : &materials[found->second];
}

MtlLibrary parse_mtl(std::string_view text, const std::string& file) {
  Parser parser(file);
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    Statement s(text.substr(0, end), capped(++number), file);
    parser.statement(s);
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return parser.take();
}

}  // namespace clrt
