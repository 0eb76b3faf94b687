// chasles: the URDF reader behind chain_from_urdf (include/chasles/urdf.hpp),
// over urdfdom. Compiled with exceptions (urdfdom's headers throw in inline
// code), and nothing leaves it as an exception: read_urdf catches all.
//
// The same semantics as python/chasles/_urdf.py, step for step (its comments
// say why), and the same refusals with the same text (the contract between
// the two loaders is the top comment of urdf.hpp). The steps:
//  1. read_source: XML text or a file path, bounded to 64 MiB.
//  2. scan: one linear pass over the text, before any parser sees it: the
//     element depth (bounded to 64: urdfdom's XML parser recurses once per
//     level and takes quadratic time) and the attributes of an element
//     (bounded to 256: quadratic time too), and what the loader checks itself in
//     the links' <inertial> and the joints' <origin>, <axis>, <limit>,
//     <parent>, <child>. urdfdom does not report everything it cannot read
//     in what it returns (a <mass value="nan"/> is logged, and the link kept
//     with mass 0), so the verdict on these elements is read here, from the
//     text, never from console_bridge's log: the inertias used are the ones
//     read here.
//  3. the checks on what the scan read (finite numbers, masses >= 0,
//     duplicate names, loops), before urdfdom: urdfdom never sees a
//     description whose joints form a loop (it would build shared_ptr cycles
//     that outlive it, even when it refuses the description).
//  4. urdfdom's parse (its structure checks), its log captured for the
//     error text only.
//  5. the walk from the base to the tip and down the side branches (an
//     explicit stack: a side branch of 25,000 links is no deeper a call
//     stack than one link), with the overflow checks.
#include "chasles/urdf.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

namespace chasles {
namespace detail {
namespace {

using Matrix4 = Eigen::Matrix4d;
using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;

/// The bounds on a description (the contract of urdf.hpp): its size, and
/// how deep its elements nest (a URDF nests about 6 deep:
/// robot > link > visual > geometry > mesh).
constexpr std::size_t max_bytes = std::size_t{64} << 20;
constexpr int max_depth = 64;
/// And the attributes of one element (a URDF element has at most 10 or
/// so): urdfdom's XML parser (TinyXML) checks each new attribute against
/// the element's others, quadratic time: 20,000 attributes (200 kB) took
/// 1.7 s of CPU, the 270,000 of a 2.7 MB element would take minutes.
constexpr int max_attributes = 256;

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error("chain_from_urdf: " + message); }

std::string quoted(const std::string& s) { return "'" + s + "'"; }

/// The shortest text that reads back as x (std::to_chars), as Python's repr
/// prints a float: -1.5, 1, 1e+308.
std::string shortest(double x) {
  char text[64];
  const auto r = std::to_chars(text, text + sizeof text, x);
  return std::string(text, r.ptr);
}

// ---- 1. The source: XML text or a path.

/// The description's text, without a byte-order mark: `source` itself when
/// it starts with '<' (after an optional UTF-8 byte-order mark and blanks),
/// otherwise the regular file it names, read with the bound.
std::string read_source(const std::string& source) {
  static constexpr char utf8_bom[] = "\xEF\xBB\xBF";
  const std::size_t start = source.compare(0, 3, utf8_bom) == 0 ? 3 : 0;
  const std::size_t first = source.find_first_not_of(" \t\r\n\f\v", start);
  if (first != std::string::npos && source[first] == '<') {
    if (source.size() - start > max_bytes)
      fail("the description is larger than 64 MiB, the bound on a URDF description");
    return source.substr(start);
  }
  const std::string path = quoted(source);
  struct stat st{};
  if (::stat(source.c_str(), &st) != 0) fail("cannot open the file " + path);
  if (S_ISDIR(st.st_mode)) fail(path + " is a directory, not a URDF file");
  if (!S_ISREG(st.st_mode)) fail(path + " is not a regular file");
  const std::string too_large = path + " is larger than 64 MiB, the bound on a URDF description";
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) fail(too_large);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(source.c_str(), "rb"), &std::fclose);
  if (!file) fail("cannot open the file " + path);
  // Never more than the bound + 1 byte, whatever the file grew to since stat.
  std::string text(static_cast<std::size_t>(st.st_size) + 1, '\0');
  std::size_t size = 0;
  for (;;) {
    if (size == text.size()) text.resize(std::min(max_bytes + 1, 2 * text.size()));
    const std::size_t got = std::fread(&text[size], 1, text.size() - size, file.get());
    size += got;
    if (size > max_bytes) fail(too_large);
    if (got == 0) break;
  }
  if (std::ferror(file.get())) fail("cannot open the file " + path);
  text.resize(size);
  if (text.compare(0, 3, utf8_bom) == 0) text.erase(0, 3);
  return text;
}

// ---- 2. The scan.

/// An attribute: its name and value, views of the text (or, for a value
/// with entities, of its decoded copy in Scan::decoded).
using Attribute = std::pair<std::string_view, std::string_view>;

/// An element the loader reads itself: whether there is one, and its
/// attributes (Scan::attributes[first, first + count)).
struct Element {
  bool present = false;
  std::uint32_t first = 0, count = 0;
};

/// A <link> of the <robot>: its name and its first <inertial>'s first
/// <origin>, <mass> and <inertia> (urdfdom reads the first of each).
struct ScannedLink {
  std::string_view name;
  bool inertial = false;
  Element origin, mass, inertia;
};

/// A <joint> of the <robot>: its name and its first <origin>, <axis>,
/// <limit>, <parent> and <child>.
struct ScannedJoint {
  std::string_view name;
  Element origin, axis, limit, parent, child;
};

struct Scan {
  std::vector<ScannedLink> links;
  std::vector<ScannedJoint> joints;
  std::vector<Attribute> attributes;
  std::deque<std::string> decoded;  // the values written with entities, decoded (stable addresses)

  /// The value of the attribute `name` of e, if it has one.
  const std::string_view* get(const Element& e, std::string_view name) const {
    for (std::uint32_t k = e.first; k < e.first + e.count; ++k)
      if (attributes[k].first == name) return &attributes[k].second;
    return nullptr;
  }
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// White space between a tag's parts, as urdfdom's XML parser (TinyXML)
/// reads it: also form feed and vertical tab.
bool is_space(char c) { return is_blank(c) || c == '\f' || c == '\v'; }

/// Where the text stops being UTF-8 (its size if it is). The XML parser
/// reads a byte that starts a multi-byte character together with the bytes
/// after it, whatever they are: in text that is not UTF-8, it would read a
/// '<' or a quote as part of a character where the scan sees markup, and
/// the two would see different elements.
std::size_t utf8_end(const std::string& t) {
  const auto* b = reinterpret_cast<const unsigned char*>(t.data());
  const std::size_t n = t.size();
  std::size_t i = 0;
  while (i < n) {
    if (n - i >= 8) {  // eight ASCII bytes at a time
      std::uint64_t word;
      std::memcpy(&word, b + i, 8);
      if (!(word & 0x8080808080808080ull)) {
        i += 8;
        continue;
      }
    }
    const unsigned c = b[i];
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len = 0;
    unsigned lo = 0x80, hi = 0xBF;  // the second byte's range
    if (c >= 0xC2 && c <= 0xDF) {
      len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      len = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      len = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (n - i < len || b[i + 1] < lo || b[i + 1] > hi) return i;
    for (std::size_t k = 2; k < len; ++k)
      if (b[i + k] < 0x80 || b[i + k] > 0xBF) return i;
    i += len;
  }
  return n;
}

/// The characters that end a tag's name (blanks, '>', '/', '<') and an
/// attribute's name (also '=' and quotes), one table lookup per character.
struct Stops {
  bool name[256] = {}, attribute[256] = {};
  constexpr Stops() {
    for (const char c : {' ', '\t', '\r', '\n', '\f', '\v', '>', '/', '<'}) name[static_cast<unsigned char>(c)] = true;
    for (const char c : {' ', '\t', '\r', '\n', '\f', '\v', '>', '/', '=', '"', '\''})
      attribute[static_cast<unsigned char>(c)] = true;
  }
};
constexpr Stops stop_tables{};

/// What an XML parser makes of an attribute value: the five named entities
/// and character references decoded (anything else is kept as written: it
/// is not a number, which is all the loader reads in these values).
std::string decode(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    const std::size_t end = raw.find(';', i);
    if (end == std::string_view::npos || end - i > 12) {
      out += raw[i];
      continue;
    }
    const std::string_view name = raw.substr(i + 1, end - i - 1);
    static const std::pair<const char*, char> kNamed[] = {
        {"lt", '<'}, {"gt", '>'}, {"amp", '&'}, {"quot", '"'}, {"apos", '\''}};
    bool done = false;
    for (const auto& [entity, ch] : kNamed)
      if (name == entity) {
        out += ch;
        done = true;
      }
    if (!done && name.size() >= 2 && name[0] == '#') {
      const bool hex = name[1] == 'x';
      unsigned long code = 0;
      const char* b = name.data() + (hex ? 2 : 1);
      const auto r = std::from_chars(b, name.data() + name.size(), code, hex ? 16 : 10);
      if (r.ec == std::errc() && r.ptr == name.data() + name.size() && code > 0 && code < 0x80) {
        out += static_cast<char>(code);  // numbers and blanks are ASCII; others stay as written
        done = true;
      }
    }
    if (done)
      i = end;
    else
      out += raw[i];
  }
  return out;
}

/// The elements the scan reads (an index into the path of names below the
/// <robot>), so that the attributes of no other element are decoded.
enum class Role {
  none,
  robot,
  link,
  inertial,
  link_origin,
  mass,
  inertia,
  joint,
  joint_origin,
  axis,
  limit,
  parent,
  child,
  other
};

/// Past the end of the XML declaration or processing instruction at `p`
/// ("<?..."): its first '>', where urdfdom's XML parser (TinyXML) resumes
/// too, but for one case, which is refused: TinyXML reads the quoted values
/// of "<?xml"'s pseudo-attributes whole, a '>' in them included, so a '>'
/// inside a quoted value does not end the markup for it. The scan follows
/// the quotes as TinyXML can: a quote after '=' (blanks, and the bytes of
/// multi-byte characters, between them) opens a value, the same quote
/// closes it; a quote after '=' inside a value, or one that neither opens
/// nor closes a value, and a value still open at the first '>', are refused
/// (not well-formed XML: a pseudo-attribute's value holds no quote, '<' or
/// '>'). Before this rule, a '<' in the declaration's version hid the whole
/// robot, and a loop of its joints, from the checks, and urdfdom leaked the
/// loop's shared_ptr cycle. (tinyxml2, under newer urdfdom, ends any "<?" at
/// its first "?>", never before the first '>': the depth bound holds.)
const char* processing_instruction_end(const char* begin, const char* p, const char* end) {
  const char* const start = p;
  char open = 0;  // the quote of the value being read, or 0
  char last = 0;  // the last character before this one, blanks and bytes >= 0x80 skipped
  for (p += 2; p < end && *p != '>'; ++p) {
    const char c = *p;
    if (c == '"' || c == '\'') {
      if (last == '=') {
        if (open) break;  // a value opened inside a value
        open = c;
      } else if (c == open) {
        open = 0;
      } else if (!open) {
        break;  // a quote that opens no value
      }
    }
    if (!std::strchr(" \t\r\n\v\f", c) && static_cast<unsigned char>(c) < 0x80) last = c;
  }
  if (p == end && !open) return end;  // no '>': the parser refuses the document
  if (p < end && *p == '>' && !open) return p + 1;
  fail("not well-formed XML: the declaration or processing instruction at byte " + std::to_string(start - begin) +
       " has a quote that opens no value, or a value that holds a quote or a '>'");
}

/// One linear pass over the text (see the top of this file). Refuses a
/// document nested more than max_depth deep; reads the elements of Role.
/// Its view of the structure is the XML parser's on every well-formed
/// document; on others the parser refuses the document, and the depth bound
/// holds whatever the scan makes of it: a comment or CDATA section ends at
/// its "-->" or "]]>" as in the parser, and every other markup ("<?...",
/// "<!DOCTYPE ...", "<!ELEMENT ...") at its first '>', never later than
/// where the parser resumes, so that no element the parser sees is hidden
/// from the count.
Scan scan(const std::string& text) {
  const std::size_t utf8 = utf8_end(text);
  if (utf8 != text.size()) fail("the description is not UTF-8 text (byte " + std::to_string(utf8) + " of the text)");
  Scan out;
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  const char* p = begin;
  int depth = 0;
  // The role of each open element (only the first max_depth are ever open).
  Role roles[max_depth + 1] = {};
  bool seen_robot = false;
  auto find = [&](const char* from, const char* what) -> const char* {  // past `what`, or end
    const std::size_t n = std::strlen(what);
    for (;;) {
      from = static_cast<const char*>(std::memchr(from, what[0], static_cast<std::size_t>(end - from)));
      if (!from || static_cast<std::size_t>(end - from) < n) return end;
      if (std::memcmp(from, what, n) == 0) return from + n;
      ++from;
    }
  };
  while (p < end) {
    p = static_cast<const char*>(std::memchr(p, '<', static_cast<std::size_t>(end - p)));
    if (!p) break;
    const std::size_t left = static_cast<std::size_t>(end - p);
    const unsigned char next = left >= 2 ? static_cast<unsigned char>(p[1]) : 0;
    if (next == '!' && left >= 4 && p[2] == '-' && p[3] == '-') {
      p = find(p + 4, "-->");
      continue;
    }
    if (next == '!' && left >= 9 && std::memcmp(p, "<![CDATA[", 9) == 0) {
      p = find(p + 9, "]]>");
      continue;
    }
    if (next == '?') {
      p = processing_instruction_end(begin, p, end);
      continue;
    }
    if (next == '!' || next == '/') {
      // a DOCTYPE or another "<!" markup; or an end tag
      if (next == '/' && depth > 0) --depth;
      p = find(p + 2, ">");
      continue;
    }
    if (!(((next | 0x20) >= 'a' && (next | 0x20) <= 'z') || next == '_' || next == ':' || next >= 0x80)) {
      p = find(p + 1, ">");  // not a tag: the parser skips it to its '>'
      continue;
    }
    // A start tag: its name, attributes, and '>' or "/>".
    ++p;
    const char* name_begin = p;
    while (p < end && !stop_tables.name[static_cast<unsigned char>(*p)]) ++p;
    const std::string_view name(name_begin, static_cast<std::size_t>(p - name_begin));
    if (depth + 1 > max_depth)
      fail("the XML nests elements more than " + std::to_string(max_depth) + " deep, the bound on a URDF description");
    const Role up = depth > 0 ? roles[depth - 1] : Role::none;
    Role role = Role::other;
    Element* element = nullptr;
    if (depth == 0) {
      role = name == "robot" && !seen_robot ? Role::robot : Role::other;
      seen_robot = seen_robot || name == "robot";
    } else if (up == Role::robot) {
      if (name == "link") {
        role = Role::link;
        out.links.emplace_back();
      } else if (name == "joint") {
        role = Role::joint;
        out.joints.emplace_back();
      }
    } else if (up == Role::link) {
      if (name == "inertial" && !out.links.back().inertial) {
        role = Role::inertial;
        out.links.back().inertial = true;
      }
    } else if (up == Role::inertial) {
      ScannedLink& link = out.links.back();
      element = name == "origin"    ? &link.origin
                : name == "mass"    ? &link.mass
                : name == "inertia" ? &link.inertia
                                    : nullptr;
    } else if (up == Role::joint) {
      ScannedJoint& joint = out.joints.back();
      element = name == "origin"   ? &joint.origin
                : name == "axis"   ? &joint.axis
                : name == "limit"  ? &joint.limit
                : name == "parent" ? &joint.parent
                : name == "child"  ? &joint.child
                                   : nullptr;
    }
    if (element && element->present) element = nullptr;  // urdfdom reads the first
    if (element) {
      element->present = true;
      element->first = static_cast<std::uint32_t>(out.attributes.size());
    }
    const bool named = role == Role::link || role == Role::joint;
    // Attributes: name, '=', a quoted value; anything else is skipped up to
    // the tag's end (the parser refuses such a tag).
    bool self_closing = false;
    int attributes = 0;
    while (p < end) {
      while (p < end && is_space(*p)) ++p;
      if (p == end) break;
      if (*p == '>') {
        ++p;
        break;
      }
      if (*p == '/' && p + 1 < end && p[1] == '>') {
        p += 2;
        self_closing = true;
        break;
      }
      if (*p == '"' || *p == '\'') {  // a value without a name
        const char* close = static_cast<const char*>(std::memchr(p + 1, *p, static_cast<std::size_t>(end - p - 1)));
        p = close ? close + 1 : end;
        continue;
      }
      const char* attribute_begin = p;
      while (p < end && !stop_tables.attribute[static_cast<unsigned char>(*p)]) ++p;
      const std::string_view attribute(attribute_begin, static_cast<std::size_t>(p - attribute_begin));
      if (attribute.empty()) {  // a stray '/' or '='
        ++p;
        continue;
      }
      if (++attributes > max_attributes)
        fail("an element has more than " + std::to_string(max_attributes) +
             " attributes, the bound on a URDF description");
      while (p < end && is_space(*p)) ++p;
      if (p == end || *p != '=') continue;
      ++p;
      while (p < end && is_space(*p)) ++p;
      std::string_view value;
      if (p < end && (*p == '"' || *p == '\'')) {
        const char* close = static_cast<const char*>(std::memchr(p + 1, *p, static_cast<std::size_t>(end - p - 1)));
        if (!close) {
          p = end;
          break;
        }
        value = std::string_view(p + 1, static_cast<std::size_t>(close - p - 1));
        p = close + 1;
      } else {
        // Without quotes, as the parser reads it: up to a space, '/' or '>'
        // (with a quote in it, the parser refuses the document).
        const char* value_begin = p;
        while (p < end && !is_space(*p) && *p != '/' && *p != '>' && *p != '"' && *p != '\'') ++p;
        value = std::string_view(value_begin, static_cast<std::size_t>(p - value_begin));
      }
      if (element || (named && attribute == "name")) {
        std::string_view decoded = value;
        if (value.find('&') != std::string_view::npos) {
          out.decoded.push_back(decode(value));
          decoded = out.decoded.back();
        }
        if (element) {
          out.attributes.emplace_back(attribute, decoded);
          ++element->count;
        } else if (role == Role::link) {
          out.links.back().name = decoded;
        } else {
          out.joints.back().name = decoded;
        }
      }
    }
    if (!self_closing) roles[depth++] = role;
  }
  return out;
}

// ---- 3. The checks on what the scan read.

/// For a number that from_chars read whole but found out of range: whether
/// it underflows (nearer to 0 than half the smallest subnormal) rather than
/// overflows, from the decimal exponent of its first nonzero digit (negative
/// only for a magnitude below 1; overflow needs one above 308).
bool underflows(std::string_view s) {
  if (!s.empty() && s.front() == '-') s.remove_prefix(1);
  // the first nonzero digit, the k-th digit of the mantissa, stands at the
  // place 10^(int_digits - 1 - k)
  long long int_digits = 0, k = -1, digits = 0;
  bool point = false;
  std::size_t i = 0;
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] == '.') {
      point = true;
      continue;
    }
    if (!point) ++int_digits;
    if (k < 0 && s[i] != '0') k = digits;
    ++digits;
  }
  if (k < 0) return true;  // all zeros (from_chars reads them; not reached)
  long long exponent = 0;
  bool negative = false;
  if (i < s.size()) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) negative = s[i++] == '-';
    for (; i < s.size() && exponent < 1000000; ++i) exponent = 10 * exponent + (s[i] - '0');
  }
  return int_digits - 1 - k + (negative ? -exponent : exponent) < 0;
}

/// A number as urdfdom and the XML specification write it (optional sign,
/// digits, fraction, exponent), with surrounding blanks; false for anything
/// else, and for NaN, infinities and overflow ("1e400"): they are not
/// finite numbers. A number too small for a double ("1e-400") reads as a
/// zero of its sign, as the nearest double (Python's float reads it so).
bool parse_number(std::string_view s, double& x) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || !((s.front() >= '0' && s.front() <= '9') || s.front() == '.' || s.front() == '-')) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x, std::chars_format::general);
  if (r.ptr != s.data() + s.size()) return false;
  if (r.ec == std::errc::result_out_of_range && underflows(s)) {
    x = s.front() == '-' ? -0.0 : 0.0;
    return true;
  }
  return r.ec == std::errc() && std::isfinite(x);
}

/// Three numbers separated by blanks.
bool parse_vector(std::string_view s, Vector3& v) {
  std::size_t k = 0, i = 0;
  while (true) {
    while (i < s.size() && is_blank(s[i])) ++i;
    if (i == s.size()) break;
    std::size_t j = i;
    while (j < s.size() && !is_blank(s[j])) ++j;
    if (k == 3 || !parse_number(s.substr(i, j - i), v(static_cast<Eigen::Index>(k)))) return false;
    ++k;
    i = j;
  }
  return k == 3;
}

/// "link 'L'" or "joint 'J'" and what follows, for a message (built only
/// on a refusal).
std::string named(const char* kind, std::string_view name, const char* rest = "") {
  return std::string(kind) + " '" + std::string(name) + "'" + rest;
}

/// The 4x4 pose of an <origin> (identity without one): translation xyz,
/// rotation R = Rz(yaw) Ry(pitch) Rx(roll) from rpy, through urdfdom's own
/// quaternion (urdf::Rotation::setFromRPY), as urdfdom reads it.
Matrix4 origin_pose(const Scan& s, const Element& origin, const char* kind, std::string_view name,
                    const char* inertial) {
  Matrix4 T = Matrix4::Identity();
  if (!origin.present) return T;
  Vector3 xyz = Vector3::Zero(), rpy = Vector3::Zero();
  if (const std::string_view* v = s.get(origin, "xyz"))
    if (!parse_vector(*v, xyz)) fail(named(kind, name, inertial) + " <origin xyz>: expected finite numbers");
  if (const std::string_view* v = s.get(origin, "rpy"))
    if (!parse_vector(*v, rpy)) fail(named(kind, name, inertial) + " <origin rpy>: expected finite numbers");
  urdf::Rotation q;
  q.setFromRPY(rpy.x(), rpy.y(), rpy.z());
  T.topLeftCorner<3, 3>() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
  T.topRightCorner<3, 1>() = xyz;
  return T;
}

/// A link's <inertial> as read by the scan: mass, center and inertia in the
/// link frame.
struct Inertial {
  double mass;
  Matrix4 origin;
  Matrix3 inertia;  // in the <inertial> frame
};

/// The links' inertials by link name (views of the scan's names); a link
/// without <inertial> maps to nothing.
struct Inertials {
  std::unordered_map<std::string_view, std::size_t> index;  // link name -> its entry in `of`, or npos
  std::vector<Inertial> of;
  const Inertial* find(std::string_view link) const {
    const auto it = index.find(link);
    return it == index.end() || it->second == std::string_view::npos ? nullptr : &of[it->second];
  }
};

/// The checks of the contract on every link's <inertial> and every
/// joint's numbers, duplicate names, and loops (a link that is the child
/// of two joints, or a cycle of joints): what urdfdom would read silently
/// wrong, refuse with another text, or keep as a reference cycle. Returns
/// the links' inertials.
Inertials check(const Scan& s) {
  // A name with a character reference the scan did not decode (one above
  // 0x7F, which the XML parser decodes differently with and without an XML
  // declaration): the scan could not tell which names are the same.
  auto plain = [](std::string_view name, const char* what) {
    if (name.find("&#") != std::string_view::npos)
      fail(std::string(what) + " " + quoted(std::string(name)) +
           ": a character reference (&#...;) in a name is not supported");
  };
  for (const ScannedLink& link : s.links) plain(link.name, "link");
  for (const ScannedJoint& joint : s.joints) {
    plain(joint.name, "joint");
    for (const Element* e : {&joint.parent, &joint.child})
      if (const std::string_view* link = s.get(*e, "link")) plain(*link, "link");
  }
  Inertials inertials;
  inertials.index.reserve(s.links.size());
  for (const ScannedLink& link : s.links) {
    const auto [entry, inserted] = inertials.index.emplace(link.name, std::string_view::npos);
    if (!inserted) fail("duplicate link name " + quoted(std::string(link.name)));
    if (!link.inertial) continue;
    Inertial in{0.0, origin_pose(s, link.origin, "link", link.name, " <inertial>"), Matrix3::Zero()};
    const std::string_view* mass = s.get(link.mass, "value");
    if (!mass || !parse_number(*mass, in.mass)) fail(named("link", link.name, " <mass>: expected finite numbers"));
    if (in.mass < 0)
      fail(named("link", link.name, " <mass>: negative mass ") + shortest(in.mass) + " (a mass is >= 0)");
    double I[6];
    static const char* const kNames[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
    for (int k = 0; k < 6; ++k) {
      const std::string_view* v = s.get(link.inertia, kNames[k]);
      if (!v || !parse_number(*v, I[k])) fail(named("link", link.name, " <inertia>: expected finite numbers"));
    }
    in.inertia << I[0], I[1], I[2], I[1], I[3], I[4], I[2], I[4], I[5];
    entry->second = inertials.of.size();
    inertials.of.push_back(in);
  }
  std::unordered_set<std::string_view> names;
  names.reserve(s.joints.size());
  // child link -> the joint (its index in s.joints) whose child it is
  std::unordered_map<std::string_view, std::size_t> parent_of;
  parent_of.reserve(s.joints.size());
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const ScannedJoint& joint = s.joints[j];
    if (!names.insert(joint.name).second) fail("duplicate joint name " + quoted(std::string(joint.name)));
    Vector3 v;
    for (const char* attribute : {"xyz", "rpy"})  // (urdfdom's pose is the one used)
      if (const std::string_view* value = s.get(joint.origin, attribute))
        if (!parse_vector(*value, v))
          fail(named("joint", joint.name, " <origin ") + attribute + ">: expected finite numbers");
    if (const std::string_view* xyz = s.get(joint.axis, "xyz"))
      if (!parse_vector(*xyz, v)) fail(named("joint", joint.name, " <axis xyz>: expected finite numbers"));
    for (std::uint32_t k = joint.limit.first; k < joint.limit.first + joint.limit.count; ++k) {
      const auto& [attribute, value] = s.attributes[k];
      double x;
      if ((attribute == "lower" || attribute == "upper" || attribute == "velocity" || attribute == "effort") &&
          !parse_number(value, x))
        fail(named("joint", joint.name, " <limit>: expected finite numbers"));
    }
    const std::string_view* child = s.get(joint.child, "link");
    if (!child || !s.get(joint.parent, "link")) continue;  // urdfdom refuses it
    const auto [it, inserted] = parent_of.emplace(*child, j);
    if (!inserted)
      fail(named("link", *child, " is the child of joints ") + quoted(std::string(s.joints[it->second].name)) +
           " and " + quoted(std::string(joint.name)) + ": a loop (URDF describes trees)");
  }
  // Each link has one parent joint at most: a loop is a walk up from a
  // joint that comes back to a joint of the same walk. Each joint is walked
  // once (walked[j]: the walk that saw joint j).
  std::vector<std::size_t> walked(s.joints.size(), std::string_view::npos);
  for (std::size_t w = 0; w < s.joints.size(); ++w) {
    for (std::size_t j = w;;) {
      const std::string_view* parent = s.get(s.joints[j].parent, "link");
      if (!parent || !s.get(s.joints[j].child, "link")) break;
      if (walked[j] != std::string_view::npos) {
        if (walked[j] == w) fail("a loop through link " + quoted(std::string(*s.get(s.joints[j].child, "link"))));
        break;
      }
      walked[j] = w;
      const auto up = parent_of.find(*parent);
      if (up == parent_of.end()) break;
      j = up->second;
    }
  }
  return inertials;
}

// ---- 4. urdfdom.

/// Collects urdfdom's error messages (console_bridge's log) while one
/// description is parsed, for the error text only: the verdict never
/// depends on them (an application may set console_bridge's level to NONE,
/// or log from another thread). console_bridge has one global handler: this
/// one is installed for the parse (a mutex serializes the loaders), takes
/// the messages of the loading thread, and passes those of every other
/// thread on to the handler it replaced.
class Capture : public console_bridge::OutputHandler {
 public:
  explicit Capture(console_bridge::OutputHandler* previous) : previous_(previous) {}
  // The application's handler may come from code compiled without RTTI
  // (this project's tests are), whose objects UBSan's vptr check cannot
  // type: it is not applied to the call that passes messages on.
#if defined(__clang__)
  __attribute__((no_sanitize("vptr")))
#endif
  void log(const std::string& text, console_bridge::LogLevel level, const char* file, int line) override {
    if (std::this_thread::get_id() != owner_) {
      if (previous_) previous_->log(text, level, file, line);
      return;
    }
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;  // warnings are not the reason
    if (!messages.empty()) messages += "; ";
    messages += text;
  }
  std::string messages;

 private:
  console_bridge::OutputHandler* previous_;
  std::thread::id owner_ = std::this_thread::get_id();
};

std::mutex& console_mutex() {
  static std::mutex m;
  return m;
}

urdf::ModelInterfaceSharedPtr parse(const std::string& text) {
  const std::lock_guard<std::mutex> lock(console_mutex());
  Capture capture(console_bridge::getOutputHandler());
  console_bridge::useOutputHandler(&capture);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(text);
  } catch (...) {
    console_bridge::restorePreviousOutputHandler();
    throw;
  }
  console_bridge::restorePreviousOutputHandler();
  if (!model)
    fail("urdfdom refused the description: " + (capture.messages.empty()
                                                    ? "no reason given (console_bridge's log level hides its messages)"
                                                    : capture.messages));
  return model;
}

/// urdfdom's links hold their children by shared_ptr: a loop in the joints
/// is a reference cycle that outlives the model. check() refuses every loop
/// before urdfdom builds anything; this clears the links' references on
/// every way out all the same (defence in depth: a model without cycles
/// frees itself either way).
struct ReleaseCycles {
  const urdf::ModelInterfaceSharedPtr& model;
  ~ReleaseCycles() {
    if (!model) return;
    for (const auto& entry : model->links_) {
      entry.second->child_links.clear();
      entry.second->child_joints.clear();
      entry.second->parent_joint.reset();
    }
    model->root_link_.reset();
  }
};

// ---- 5. The walk.

struct Part {
  double mass;
  Vector3 com;
  Matrix3 inertia;  // about com
};

bool finite(const Matrix4& T) { return T.allFinite(); }

/// m (|d|^2 1 - d d^T) = -m [d]^2 entry by entry, as python/chasles/_urdf.py
/// writes it: the diagonal as sums of two squares, m (d_y^2 + d_z^2), ...,
/// never |d|^2 - d_z^2, which cancels where one component dominates (a link
/// 13 m up the z axis lost 5e-14 of a 0.2 kg m^2 moment that way).
Matrix3 parallel_axis(double m, const Vector3& d) {
  const double x = d.x(), y = d.y(), z = d.z();
  Matrix3 P;
  P << y * y + z * z, -x * y, -x * z, -x * y, x * x + z * z, -y * z, -x * z, -y * z, x * x + y * y;
  return m * P;
}

/// One body from several, all in one frame: the total mass, the
/// mass-weighted center, each inertia moved there by the parallel-axis
/// theorem, I + m (|d|^2 1 - d d^T).
Part merge(const std::vector<Part>& parts) {
  Part out{0.0, Vector3::Zero(), Matrix3::Zero()};
  for (const Part& p : parts) out.mass += p.mass;
  if (!(out.mass > 0)) {
    out.mass = 0.0;
    for (const Part& p : parts) out.inertia += p.inertia;
    return out;
  }
  for (const Part& p : parts) out.com += p.mass * p.com;
  out.com /= out.mass;
  for (const Part& p : parts) out.inertia += p.inertia + parallel_axis(p.mass, p.com - out.com);
  return out;
}

/// A pose of urdfdom's (the joints' <origin>, which check() read as finite).
Matrix4 pose(const urdf::Pose& p) {
  const urdf::Rotation& q = p.rotation;
  Matrix4 T = Matrix4::Identity();
  T.topLeftCorner<3, 3>() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
  T.topRightCorner<3, 1>() = Vector3(p.position.x, p.position.y, p.position.z);
  return T;
}

UrdfDescription read(const std::string& source, const std::string& tip_link, const std::string& base_link_in) {
  const std::string text = read_source(source);
  const Scan scanned = scan(text);
  const Inertials inertials = check(scanned);
  urdf::ModelInterfaceSharedPtr model;
  const ReleaseCycles release{model};
  model = parse(text);

  const urdf::LinkConstSharedPtr tip = model->getLink(tip_link);
  if (!tip)
    throw std::runtime_error("chain_from_urdf(tip_link): no link named " + quoted(tip_link) + " in the description");
  if (!base_link_in.empty() && !model->getLink(base_link_in))
    throw std::runtime_error("chain_from_urdf(base_link): no link named " + quoted(base_link_in) +
                             " in the description");
  const std::string base_link = base_link_in.empty() ? model->getRoot()->name : base_link_in;

  // From the tip up to the base, by each link's parent joint (check()
  // refused a link that is the child of two joints, and loops: the walk
  // ends at the root; the bound on its length is a defence).
  std::vector<urdf::JointConstSharedPtr> path;
  for (const urdf::Link* link = tip.get(); link->name != base_link;) {
    if (!link->parent_joint || path.size() > model->joints_.size())
      fail("tip_link " + quoted(tip_link) + " is not below base_link " + quoted(base_link));
    path.push_back(link->parent_joint);
    const urdf::LinkConstSharedPtr parent = model->getLink(link->parent_joint->parent_link_name);
    if (!parent) fail("tip_link " + quoted(tip_link) + " is not below base_link " + quoted(base_link));
    link = parent.get();
  }
  std::reverse(path.begin(), path.end());
  std::unordered_set<std::string_view> on_path{base_link};
  for (const auto& joint : path) on_path.insert(joint->child_link_name);

  // A link's <inertial> in the base frame at home (T_link: the link frame
  // there), as the scan read it.
  auto add_inertial = [&](const std::string& link, const Matrix4& T_link, std::vector<Part>& parts) {
    const Inertial* found = inertials.find(link);
    if (!found) return;
    const Inertial& in = *found;
    const Matrix4 T = T_link * in.origin;
    const Matrix3 R = T.topLeftCorner<3, 3>();
    parts.push_back({in.mass, T.topRightCorner<3, 1>(), R * in.inertia * R.transpose()});
  };
  auto require_finite_pose = [](const Matrix4& T, const urdf::Joint& joint) {
    if (!finite(T))
      fail("joint " + quoted(joint.name) + ": the pose of link " + quoted(joint.child_link_name) +
           " at home is not finite (overflow)");
  };

  // Links hanging off the chain ride rigidly on the chain link they hang
  // from: fixed joints as they are, moving joints off the chain at zero.
  // Depth first, children in their order (the order of the Python loader's
  // sums), on an explicit stack.
  std::vector<std::pair<const urdf::Link*, Matrix4>> stack;
  auto push_children = [&](const urdf::Link& link, const Matrix4& T_link) {
    const std::size_t first = stack.size();
    for (const auto& joint : link.child_joints) {
      if (on_path.count(joint->child_link_name)) continue;
      const Matrix4 T_child = T_link * pose(joint->parent_to_joint_origin_transform);
      require_finite_pose(T_child, *joint);
      stack.emplace_back(model->getLink(joint->child_link_name).get(), T_child);
    }
    std::reverse(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end());
  };
  auto hanging = [&](const urdf::Link& link, const Matrix4& T_link, std::vector<Part>& parts) {
    push_children(link, T_link);
    while (!stack.empty()) {
      const std::pair<const urdf::Link*, Matrix4> top = stack.back();
      stack.pop_back();
      add_inertial(top.first->name, top.second, parts);
      push_children(*top.first, top.second);
    }
  };

  UrdfDescription d;
  std::vector<Eigen::Matrix<double, 6, 1>> screws;
  std::vector<double> lower, upper, velocity, effort;
  std::vector<std::vector<Part>> bodies;  // per moving joint, the links it moves
  Matrix4 T = Matrix4::Identity();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& joint : path) {
    const std::string what = "joint " + quoted(joint->name);
    const int kind = joint->type;
    if (kind == urdf::Joint::FLOATING || kind == urdf::Joint::PLANAR)
      fail(what + " is " + (kind == urdf::Joint::FLOATING ? "floating" : "planar") +
           ": a serial chain has joints of one degree of freedom");
    if (kind != urdf::Joint::REVOLUTE && kind != urdf::Joint::CONTINUOUS && kind != urdf::Joint::PRISMATIC &&
        kind != urdf::Joint::FIXED)
      fail(what + ": unknown joint type");
    if (joint->mimic) fail(what + ": <mimic> joints are not supported");
    T = T * pose(joint->parent_to_joint_origin_transform);
    require_finite_pose(T, *joint);
    if (kind != urdf::Joint::FIXED) {
      Vector3 axis(joint->axis.x, joint->axis.y, joint->axis.z);
      if (!axis.allFinite()) fail(what + " <axis xyz>: expected finite numbers");
      // A direction: scaled by its largest component first, so that
      // (1e308, 1e308, 0) normalizes without overflow.
      const double largest = axis.cwiseAbs().maxCoeff();
      if (!(largest > 0)) fail(what + ": <axis xyz> is zero");
      axis /= largest;
      Vector3 w = T.topLeftCorner<3, 3>() * (axis / axis.norm());
      w /= w.norm();
      Eigen::Matrix<double, 6, 1> s;
      if (kind == urdf::Joint::PRISMATIC)
        s << w, Vector3::Zero();
      else
        s << -w.cross(Vector3(T.topRightCorner<3, 1>())), w;
      if (!s.allFinite()) fail(what + ": its screw at home is not finite (overflow)");
      screws.push_back(s);
      const urdf::JointLimitsSharedPtr& limit = joint->limits;
      double lo = -inf, hi = inf;
      if (kind != urdf::Joint::CONTINUOUS) {
        if (!limit)
          fail(what + ": a " + (kind == urdf::Joint::PRISMATIC ? "prismatic" : "revolute") + " joint needs a <limit>");
        lo = limit->lower;
        hi = limit->upper;
        if (!(std::isfinite(lo) && std::isfinite(hi))) fail(what + " <limit>: expected finite numbers");
        if (lo > hi) fail(what + " <limit>: lower " + shortest(lo) + " > upper " + shortest(hi));
      }
      if (limit) {
        if (!(std::isfinite(limit->velocity) && std::isfinite(limit->effort)))
          fail(what + " <limit>: expected finite numbers");
        if (limit->velocity < 0) fail(what + " <limit>: negative velocity " + shortest(limit->velocity));
        if (limit->effort < 0) fail(what + " <limit>: negative effort " + shortest(limit->effort));
      }
      d.names.push_back(joint->name);
      d.types.push_back(kind == urdf::Joint::PRISMATIC    ? JointType::prismatic
                        : kind == urdf::Joint::CONTINUOUS ? JointType::continuous
                                                          : JointType::revolute);
      lower.push_back(lo);
      upper.push_back(hi);
      velocity.push_back(limit ? limit->velocity : inf);
      effort.push_back(limit ? limit->effort : inf);
      bodies.emplace_back();
    }
    if (!bodies.empty()) {  // links before the first moving joint belong to the base
      const urdf::LinkConstSharedPtr child = model->getLink(joint->child_link_name);
      add_inertial(child->name, T, bodies.back());
      hanging(*child, T, bodies.back());
    }
  }
  if (screws.empty())
    fail("no revolute, continuous or prismatic joint from " + quoted(base_link) + " to " + quoted(tip_link));

  d.joints.resize(screws.size());
  for (std::size_t k = 0; k < screws.size(); ++k) {
    UrdfDescription::Joint& j = d.joints[k];
    Eigen::Map<Eigen::Matrix<double, 6, 1>>(j.screw.data()) = screws[k];
    j.lower = lower[k];
    j.upper = upper[k];
    j.velocity = velocity[k];
    j.effort = effort[k];
    const Part body = merge(bodies[k]);
    if (!(std::isfinite(body.mass) && body.com.allFinite() && body.inertia.allFinite()))
      fail("joint " + quoted(d.names[k]) + ": the mass properties of the links it moves are not finite (overflow)");
    j.mass = body.mass;
    Eigen::Map<Vector3>(j.com.data()) = body.com;
    std::copy(body.inertia.data(), body.inertia.data() + 9, j.inertia.begin());
  }
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(d.home.data()) = T;
  return d;
}

}  // namespace

UrdfDescription read_urdf(const std::string& xml_or_path, const std::string& tip_link,
                          const std::string& base_link) noexcept {
  try {
    return read(xml_or_path, tip_link, base_link);
  } catch (const std::exception& e) {
    UrdfDescription d;
    d.error = e.what();
    return d;
  } catch (...) {
    UrdfDescription d;
    d.error = "chain_from_urdf: an unknown exception while reading the description";
    return d;
  }
}

}  // namespace detail
}  // namespace chasles
