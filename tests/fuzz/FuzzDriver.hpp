// ros2vtk tests — a seeded mutation driver for the parsers of untrusted input, used where
// libFuzzer is not available (Debian's gcc has none; clang is not installed here). It reads a
// corpus folder, then for a fixed number of iterations picks an entry, applies 1-8 random edits
// (bit flips, interesting bytes, inserted dictionary tokens, deleted / duplicated / spliced
// ranges, truncation) and hands the result to the target. Runs under ASan + UBSan, so a crash,
// an out-of-bounds access, undefined behaviour or a giant allocation fails the run; the same
// seed gives the same inputs. Deterministic counts, never a time budget.
#ifndef ros2vtk_tests_fuzz_FuzzDriver_hpp
#define ros2vtk_tests_fuzz_FuzzDriver_hpp

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ros2vtk_fuzz {

struct FuzzTarget
{
  std::string name;
  /// Tokens worth inserting whole (XML tags, YAML anchors, ...).
  std::vector<std::string> dictionary;
  /// Feeds one input; returns true when the input was accepted (counted only).
  std::function<bool(const std::string& input)> run;
  std::size_t max_input_bytes = 64 * 1024;
};

struct FuzzReport
{
  std::size_t inputs = 0;
  std::size_t accepted = 0;
};

/// Every regular file of `folder` (sorted by name), or an empty list.
std::vector<std::string> read_corpus(const std::string& folder);

/// Runs the corpus entries as they are, then `iterations` mutated inputs from `seed`.
FuzzReport fuzz(const FuzzTarget& target, const std::vector<std::string>& corpus,
  std::size_t iterations, std::uint32_t seed);

} // namespace ros2vtk_fuzz

#endif
