// Fuzz target: the URDF loader, chain_from_urdf (include/chasles/urdf.hpp,
// src/urdf.cpp, compiled into this target so that it is instrumented), over
// urdfdom.
//
// Input: the tip link's name, a newline, then the description's XML text
// (the base link is the root). Inputs whose text is not XML text by the
// loader's rule (after an optional byte-order mark and blanks, '<') are
// skipped: the loader would read them as a file path.
// Properties, every input, in double and in float:
// - it returns (the sanitizers see every read out of bounds, every leak of
//   urdfdom's tree, and a stack overflow), with a chain or an error, never
//   both, never neither; an error starts with "chain_from_urdf";
// - a chain validates (Chain::validate()), and everything in it is finite:
//   screws, home pose, link inertias; limits are not NaN (+-inf are the
//   limits of a continuous joint, or of a joint without <limit>); one name
//   per joint.
#include <chasles/urdf.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void require(bool ok, const char* property, const std::string& detail) {
  if (ok) return;
  std::fprintf(stderr, "property violated: %s\n%s\n", property, detail.c_str());
  std::abort();
}

template <typename T>
void check(const std::string& text, const std::string& tip) {
  const auto r = chasles::chain_from_urdf<T, 16>(text, tip);
  require(r.chain.has_value() != !r.error.empty(), "a chain or an error", r.error);
  if (!r) {
    require(r.error.rfind("chain_from_urdf", 0) == 0, "the error names the loader", r.error);
    return;
  }
  const auto& c = *r.chain;
  require(static_cast<bool>(c.validate()), "the chain validates", "");
  require(static_cast<Eigen::Index>(r.joint_names.size()) == c.n_joints(), "one name per joint", "");
  bool finite = c.space_screws().allFinite() && c.home().matrix().allFinite();
  for (Eigen::Index i = 0; i < c.n_joints(); ++i) {
    const auto& G = c.link_inertias()[static_cast<std::size_t>(i)];
    finite = finite && std::isfinite(G.mass()) && G.com().allFinite() && G.inertia().allFinite();
    finite = finite && !std::isnan(c.lower()(i)) && !std::isnan(c.upper()(i)) && !std::isnan(c.velocity_limits()(i)) &&
             !std::isnan(c.effort_limits()(i));
  }
  require(finite, "everything in the chain is finite", "");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = input.find('\n');
  if (newline == std::string::npos) return 0;
  const std::string tip = input.substr(0, newline);
  const std::string text = input.substr(newline + 1);
  const std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  const std::size_t first = text.find_first_not_of(" \t\r\n\f\v", start);
  if (first == std::string::npos || text[first] != '<') return 0;  // a path
  check<double>(text, tip);
  check<float>(text, tip);
  return 0;
}
