#include "scene/obj_chunk.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

#include "scene/memory_limit.hpp"

namespace clrt {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Thrown at a malformed line and caught where the slice's parse began.
struct Malformed {
  ObjPlace where;
  std::string message;
};

// At most 40 bytes of a word: a 100 MB word must not be echoed whole into a message.
std::string quoted(std::string_view word) {
  constexpr std::size_t kMax = 40;
  return "'" + std::string(word.substr(0, kMax)) + (word.size() > kMax ? "...'" : "'");
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The common short decimal (as "-0.1234567", no exponent) read without std::from_chars, with the
// same result: its digits make an integer m <= 2^24 and it is m / 10^k with k <= 10, where both
// are exact floats, so one division rounds it correctly (Clinger's fast path). Returns the end
// of the number, or nullptr for anything else (left to std::from_chars).
const char* short_decimal(const char* p, const char* end, float& value) {
  static constexpr float kPowers[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
  const bool negative = p < end && *p == '-';
  if (p < end && (*p == '-' || *p == '+')) ++p;
  std::uint32_t m = 0;
  int fraction_digits = 0;
  bool any = false;
  for (; p < end && is_digit(*p); ++p, any = true) {
    if (m > 99999999) return nullptr;
    m = m * 10 + static_cast<std::uint32_t>(*p - '0');
  }
  if (p < end && *p == '.')
    for (++p; p < end && is_digit(*p); ++p, any = true, ++fraction_digits) {
      if (m > 99999999 || fraction_digits == 10) return nullptr;
      m = m * 10 + static_cast<std::uint32_t>(*p - '0');
    }
  if (!any || m > (1u << 24) || (p < end && !is_blank(*p))) return nullptr;
  const float v = static_cast<float>(m) / kPowers[fraction_digits];
  value = negative ? -v : v;
  return p;
}

// A face corner as written: indices from 1, negative ones relative; texcoord or normal 0 when it
// has none.
struct Corner {
  std::int64_t position = 0, texcoord = 0, normal = 0;
  std::size_t column = 1;
};

// The words of one line, read left to right.
class LineReader {
 public:
  LineReader(const char* begin, const char* end, std::size_t line)
      : line_start_(begin), p_(begin), end_(end), line_(line) {}

  std::size_t line() const { return line_; }

  // Skips blanks; false at the line's end or at a word starting a comment.
  bool at_word() {
    while (p_ < end_ && is_blank(*p_)) ++p_;
    return p_ < end_ && *p_ != '#';
  }

  std::string_view take_word() {
    const char* start = p_;
    p_ = word_end(p_);
    last_end_ = p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }

  std::size_t column() const { return column_of(p_); }
  // Just past the last word taken (the keyword's at least): where a missing word would go.
  std::size_t column_past_last() const { return column_of(last_end_); }

  // A number in single precision, finite and in range.
  float number() {
    float value = 0;
    if (const char* end = short_decimal(p_, end_, value)) {
      p_ = last_end_ = end;
      return value;
    }
    const char* start = p_;
    // std::from_chars takes '-' but not '+'; "+-1" must not pass as -1.
    const char* digits = *start == '+' && start + 1 < end_ && start[1] != '-' ? start + 1 : start;
    const std::from_chars_result r = std::from_chars(digits, end_, value);
    if (r.ec == std::errc::invalid_argument || (r.ptr < end_ && !is_blank(*r.ptr))) {
      const std::size_t at = column();
      fail(at, quoted(take_word()) + " is not a number");
    }
    p_ = last_end_ = r.ptr;
    if (r.ec == std::errc::result_out_of_range)
      fail(column_of(start), quoted({start, static_cast<std::size_t>(r.ptr - start)}) + " is out of range for single precision");
    if (!std::isfinite(value))
      fail(column_of(start), quoted({start, static_cast<std::size_t>(r.ptr - start)}) + " is not a finite number");
    return value;
  }

  // v, v/vt, v//vn or v/vt/vn.
  Corner corner() {
    const char* start = p_;
    Corner c;
    c.column = column();
    c.position = index(start, "vertex");
    if (p_ < end_ && *p_ == '/') {
      ++p_;
      if (p_ == end_ || *p_ != '/') c.texcoord = index(start, "texture coordinate");
      if (p_ < end_ && *p_ == '/') {
        ++p_;
        c.normal = index(start, "normal");
      }
    }
    if (p_ < end_ && !is_blank(*p_)) bad_corner(start);
    last_end_ = p_;
    return c;
  }

  // The rest of the line, from its first word to the end of its last (a comment left out), and
  // the column it starts at; empty when no word is left.
  std::string_view rest(std::size_t& column) {
    std::string_view span;
    column = column_past_last();
    while (at_word()) {
      const char* start = p_;
      if (span.empty()) column = column_of(start);
      const char* first = span.empty() ? start : span.data();
      take_word();
      span = {first, static_cast<std::size_t>(p_ - first)};
    }
    return span;
  }

  [[noreturn]] void fail(std::size_t column, std::string message) const {
    throw Malformed{{line_, column}, std::move(message)};
  }

 private:
  const char* word_end(const char* p) const {
    while (p < end_ && !is_blank(*p)) ++p;
    return p;
  }

  std::size_t column_of(const char* p) const { return static_cast<std::size_t>(p - line_start_) + 1; }

  [[noreturn]] void bad_corner(const char* start) const {
    fail(column_of(start), "bad face corner " + quoted({start, static_cast<std::size_t>(word_end(start) - start)}));
  }

  // A non-zero decimal integer; any index past INT32_MAX is beyond every table a file can hold.
  std::int64_t index(const char* corner_start, const char* what) {
    const char* written = p_;
    const bool negative = p_ < end_ && *p_ == '-';
    if (negative) ++p_;
    const char* digits = p_;
    std::int64_t value = 0;
    for (; p_ < end_ && *p_ >= '0' && *p_ <= '9'; ++p_) {
      value = value * 10 + (*p_ - '0');
      if (value > INT32_MAX)
        fail(column_of(corner_start), std::string(what) + " index " + quoted({written, static_cast<std::size_t>(word_end(p_) - written)}) + " is out of range");
    }
    // Digits followed by anything but '/' or the corner's end ("0x1", "1e3") are no index.
    if (p_ == digits || (p_ < end_ && *p_ != '/' && !is_blank(*p_))) bad_corner(corner_start);
    if (value == 0) fail(column_of(corner_start), std::string(what) + " index 0 is not allowed (indices start at 1)");
    return negative ? -value : value;
  }

  const char* line_start_;
  const char* p_;
  const char* end_;
  const char* last_end_ = p_;
  std::size_t line_;
};

// Reads the numbers of a v, vn or vt line, at most `most` of them (a further one is an error);
// the first three go to `xyz`. Returns how many there were.
int numbers(LineReader& r, int most, const char* what, float xyz[3]) {
  int count = 0;
  while (r.at_word()) {
    if (count == most) r.fail(r.column(), std::string("too many numbers for ") + what);
    const float value = r.number();
    if (count < 3) xyz[count] = value;
    ++count;
  }
  return count;
}

template <class Sink>
void vertex(LineReader& r, Sink& sink) {
  float xyz[3];
  const int count = numbers(r, 6, "a vertex (x y z [w] or x y z r g b)", xyz);
  if (count < 3 || count == 5)
    r.fail(r.column_past_last(), "a vertex is x y z [w] or x y z r g b: found " + std::to_string(count) + " numbers");
  sink.position({xyz[0], xyz[1], xyz[2]});
}

template <class Sink>
void normal(LineReader& r, Sink& sink) {
  float xyz[3];
  const int count = numbers(r, 3, "a normal (x y z)", xyz);
  if (count < 3) r.fail(r.column_past_last(), "a normal is x y z: found " + std::to_string(count) + " numbers");
  sink.normal({xyz[0], xyz[1], xyz[2]});
}

template <class Sink>
void texture_coordinate(LineReader& r, Sink& sink) {
  float uvw[3] = {0, 0, 0};
  if (numbers(r, 3, "a texture coordinate (u [v [w]])", uvw) == 0)
    r.fail(r.column_past_last(), "a texture coordinate is u [v [w]]: found no number");
  sink.texcoord({uvw[0], uvw[1]});
}

// Cut into the fan (0, k, k + 1). Returns false when the sink wants no more.
template <class Sink>
bool face(LineReader& r, Sink& sink) {
  Corner first, previous;
  int count = 0;
  while (r.at_word()) {
    const Corner c = r.corner();
    if (count == 0) first = c;
    if (count >= 2 && !sink.triangle(first, previous, c, r.line())) return false;
    previous = c;
    ++count;
  }
  if (count < 3)
    r.fail(r.column_past_last(), "a face needs at least 3 corners, found " + std::to_string(count));
  if (count > 3) sink.polygon(static_cast<std::size_t>(count), r.line());
  return true;
}

// Returns false when the sink wants no more.
template <class Sink>
bool parse_line(const char* begin, const char* end, std::size_t line, Sink& sink) {
  LineReader r(begin, end, line);
  if (!r.at_word()) return true;
  const std::string_view keyword = r.take_word();
  if (keyword == "v") vertex(r, sink);
  else if (keyword == "vn") normal(r, sink);
  else if (keyword == "vt") texture_coordinate(r, sink);
  else if (keyword == "f") return face(r, sink);
  else if (keyword == "usemtl" || keyword == "mtllib") {
    std::size_t column = 1;
    const std::string_view name = r.rest(column);
    if (name.empty())
      r.fail(column, std::string(keyword) + " needs a " + (keyword == "usemtl" ? "material name" : "file name"));
    if (keyword == "usemtl") sink.use_material(name, {line, column});
    else sink.library(name, {line, column});
  }
  return true;
}

// Lines between two reports of a slice's memory: rare enough to cost nothing, often enough that a
// slice grows by at most a few MiB past the limit.
constexpr std::size_t kLinesPerMemoryReport = 4096;

// Parses `text` line by line into `sink`; returns the number of line ends it passed.
template <class Sink>
std::size_t parse_lines(std::string_view text, Sink& sink) {
  const char* p = text.data();
  const char* const end = p + text.size();
  std::size_t line = 0;
  while (p < end) {
    if (line % kLinesPerMemoryReport == 0) sink.report_memory(line);
    const auto* newline = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    const char* eol = newline ? newline : end;
    if (!parse_line(p, eol, line, sink) || !newline) break;
    p = eol + 1;
    ++line;
  }
  return line;
}

// Fills an ObjChunk.
class Collector {
 public:
  Collector(ObjChunk& out, ObjMemoryMeter& meter) : out_(out), meter_(meter) {}

  void report_memory(std::size_t line) {
    const std::uint64_t now = out_.bytes();
    const std::uint64_t used = meter_.used += now - reported_;
    reported_ = now;
    if (used > meter_.available)
      throw Malformed{{line, 1}, "loading stopped here: the mesh needs more than " + mebibytes(used) +
                                     ", " + mebibytes(meter_.available) + " available (" +
                                     meter_.source + ")"};
  }

  void position(const Vec3& p) { out_.positions.push_back(p); }
  void texcoord(const std::array<float, 2>& uv) { out_.texcoords.push_back(uv); }
  void normal(const Vec3& n) { out_.normals.push_back(n); }
  void use_material(std::string_view name, const ObjPlace& where) {
    out_.material_runs.push_back({out_.corners.index.size() / 3, std::string(name), where});
  }
  void library(std::string_view path, const ObjPlace& where) {
    out_.libraries.push_back({std::string(path), where});
  }

  bool triangle(const Corner& a, const Corner& b, const Corner& c, std::size_t) {
    for (const Corner* k : {&a, &b, &c}) {
      add(out_.corners, k->position, out_.positions.size());
      texcoord_corner(k->texcoord);
      if (k->normal == 0) out_.every_corner_has_normal = false;
      add_or_none(out_.corner_normals, k->normal, out_.normals.size());
    }
    return true;
  }

  void polygon(std::size_t corners, std::size_t line) {
    out_.polygons.push_back({out_.corners.index.size() - 3 * (corners - 2), corners, line});
  }

 private:
  // After the corner's position: ObjChunk::corner_texcoords stays empty up to the first corner
  // that names one, and from there holds one index per corner.
  void texcoord_corner(std::int64_t written) {
    ObjCornerRefs& refs = out_.corner_texcoords;
    if (written == 0 && refs.index.empty()) return;
    refs.index.resize(out_.corners.index.size() - 1, kObjNoIndex);  // the corners before, naming none
    add_or_none(refs, written, out_.texcoords.size());
  }

  static void add_or_none(ObjCornerRefs& refs, std::int64_t written, std::size_t read_so_far) {
    if (written != 0) add(refs, written, read_so_far);
    else refs.index.push_back(kObjNoIndex);
  }

  static void add(ObjCornerRefs& refs, std::int64_t written, std::size_t read_so_far) {
    if (written > 0) {
      refs.index.push_back(static_cast<std::int32_t>(written - 1));
    } else {
      refs.relative.push_back(static_cast<std::uint32_t>(refs.index.size()));
      refs.index.push_back(static_cast<std::int32_t>(static_cast<std::int64_t>(read_so_far) + written));
    }
  }

  ObjChunk& out_;
  ObjMemoryMeter& meter_;
  std::uint64_t reported_ = 0;
};

// Stops at one triangle corner and keeps its source.
class CornerFinder {
 public:
  explicit CornerFinder(std::size_t corner) : wanted_(corner) {}

  void position(const Vec3&) { ++positions_; }
  void texcoord(const std::array<float, 2>&) { ++texcoords_; }
  void normal(const Vec3&) { ++normals_; }
  void use_material(std::string_view, const ObjPlace&) {}
  void library(std::string_view, const ObjPlace&) {}

  bool triangle(const Corner& a, const Corner& b, const Corner& c, std::size_t line) {
    if (wanted_ >= seen_ + 3) {
      seen_ += 3;
      return true;
    }
    const Corner* corners[3] = {&a, &b, &c};
    const Corner& k = *corners[wanted_ - seen_];
    found_ = {{line, k.column}, k.position, k.texcoord, k.normal, positions_, texcoords_, normals_};
    return false;
  }

  void polygon(std::size_t, std::size_t) {}
  void report_memory(std::size_t) {}

  const ObjCornerSource& found() const { return found_; }

 private:
  std::size_t wanted_, seen_ = 0, positions_ = 0, texcoords_ = 0, normals_ = 0;
  ObjCornerSource found_;
};

}  // namespace

std::uint64_t ObjChunk::bytes() const {
  std::uint64_t refs = 0;
  for (const ObjCornerRefs* r : {&corners, &corner_texcoords, &corner_normals})
    refs += r->index.capacity() * sizeof(std::int32_t) + r->relative.capacity() * sizeof(std::uint32_t);
  return (positions.capacity() + normals.capacity()) * sizeof(Vec3) +
         texcoords.capacity() * sizeof(std::array<float, 2>) + refs +
         polygons.capacity() * sizeof(ObjPolygon) + material_runs.capacity() * sizeof(ObjMaterialRun) +
         libraries.capacity() * sizeof(ObjLibraryRef);
}

ObjChunk parse_obj_chunk(std::string_view text, ObjMemoryMeter& meter) {
  ObjChunk chunk;
  Collector collector(chunk, meter);
  try {
    chunk.lines = parse_lines(text, collector);
  } catch (const Malformed& m) {
    chunk.problem = ObjProblem{m.where, m.message};
  }
  return chunk;
}

ObjCornerSource find_obj_corner(std::string_view text, std::size_t corner) {
  CornerFinder finder(corner);
  parse_lines(text, finder);
  return finder.found();
}

}  // namespace clrt
