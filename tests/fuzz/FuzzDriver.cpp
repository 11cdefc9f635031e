// ros2vtk tests — the mutation loop of FuzzDriver.hpp.
#include "FuzzDriver.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace ros2vtk_fuzz {

std::vector<std::string> read_corpus(const std::string& folder)
{
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
    if (entry.is_regular_file())
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<std::string> corpus;
  for (const auto& file : files)
  {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    corpus.push_back(bytes.str());
  }
  return corpus;
}

namespace {

const unsigned char kInteresting[] = { 0x00, 0x01, 0x7f, 0x80, 0xff, 0xfe, 0xc0, 0xed, '<', '>',
  '/', '"', '\'', '&', '=', '[', ']', '{', '}', ':', '-', ' ', '\n', '*', '0', '9' };

class Mutator
{
public:
  Mutator(const FuzzTarget& target, const std::vector<std::string>& corpus, std::uint32_t seed)
    : target_(target)
    , corpus_(corpus)
    , random_(seed)
  {
  }

  std::string next()
  {
    std::string input = corpus_.empty() ? std::string() : corpus_[pick(corpus_.size())];
    const std::size_t edits = 1 + pick(8);
    for (std::size_t i = 0; i < edits; ++i)
      edit(input);
    if (input.size() > target_.max_input_bytes)
      input.resize(target_.max_input_bytes);
    return input;
  }

private:
  std::size_t pick(std::size_t n)
  {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(random_);
  }

  void edit(std::string& s)
  {
    const std::size_t at = pick(s.size() + 1);
    switch (pick(8))
    {
      case 0: // flip a bit
        if (!s.empty())
          s[pick(s.size())] ^= static_cast<char>(1u << pick(8));
        break;
      case 1: // an interesting byte, replaced or inserted
        if (!s.empty() && pick(2) == 0)
          s[pick(s.size())] = static_cast<char>(kInteresting[pick(sizeof(kInteresting))]);
        else
          s.insert(at, 1, static_cast<char>(kInteresting[pick(sizeof(kInteresting))]));
        break;
      case 2: // a dictionary token, possibly repeated (nesting, long lists)
        if (!target_.dictionary.empty())
        {
          const std::string& token = target_.dictionary[pick(target_.dictionary.size())];
          std::string repeated;
          for (std::size_t n = 1 + (pick(4) == 0 ? pick(64) : 0); n > 0; --n)
            repeated += token;
          s.insert(at, repeated);
        }
        break;
      case 3: // delete a range
        if (!s.empty())
          s.erase(at, 1 + pick(std::min<std::size_t>(s.size(), 64)));
        break;
      case 4: // duplicate a range elsewhere
        if (!s.empty())
        {
          const std::size_t from = pick(s.size());
          s.insert(at, s.substr(from, 1 + pick(std::min<std::size_t>(s.size() - from, 256))));
        }
        break;
      case 5: // splice in a range of another entry
        if (!corpus_.empty())
        {
          const std::string& other = corpus_[pick(corpus_.size())];
          if (!other.empty())
          {
            const std::size_t from = pick(other.size());
            s.insert(
              at, other.substr(from, 1 + pick(std::min<std::size_t>(other.size() - from, 512))));
          }
        }
        break;
      case 6: // truncate
        s.resize(at);
        break;
      default: // random bytes
        for (std::size_t n = 1 + pick(8); n > 0; --n)
          s.insert(pick(s.size() + 1), 1, static_cast<char>(pick(256)));
        break;
    }
  }

  const FuzzTarget& target_;
  const std::vector<std::string>& corpus_;
  std::mt19937 random_;
};

} // namespace

FuzzReport fuzz(const FuzzTarget& target, const std::vector<std::string>& corpus,
  std::size_t iterations, std::uint32_t seed)
{
  FuzzReport report;
  for (const std::string& entry : corpus)
  {
    ++report.inputs;
    report.accepted += target.run(entry) ? 1 : 0;
  }
  Mutator mutator(target, corpus, seed);
  for (std::size_t i = 0; i < iterations; ++i)
  {
    ++report.inputs;
    report.accepted += target.run(mutator.next()) ? 1 : 0;
  }
  return report;
}

} // namespace ros2vtk_fuzz
