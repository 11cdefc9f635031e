// Shared helpers of the C++ benchmark programs: a monotonic clock in milliseconds, wall-clock
// seconds (comparable with header stamps written by rclpy's time.time()), the process's RSS,
// a tiny JSON writer for the results the Python driver reads (one object on stdout), and the
// senders' paced loop.
#ifndef ros2vtk_bench_BenchCommon_hpp
#define ros2vtk_bench_BenchCommon_hpp

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace bench {

using Clock = std::chrono::steady_clock;

inline double ms_between(Clock::time_point start, Clock::time_point end)
{
  return std::chrono::duration<double, std::milli>(end - start).count();
}

/// Seconds since the epoch (system clock), as header stamps are.
inline double wall_seconds()
{
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

/// Resident set size of this process in MiB (VmRSS of /proc/self/status), -1 when unknown.
inline double rss_mib()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmRSS:", 0) == 0)
    {
      std::istringstream fields(line.substr(6));
      double kib = -1;
      fields >> kib;
      return kib / 1024.0;
    }
  }
  return -1.0;
}

/// Builds one JSON object, key by key (keys and strings are plain ASCII here).
class JsonObject
{
public:
  JsonObject& number(const std::string& key, double value)
  {
    std::ostringstream out;
    out.precision(9);
    out << value;
    return raw(key, out.str());
  }
  JsonObject& text(const std::string& key, const std::string& value)
  {
    std::string escaped;
    for (char c : value)
    {
      if (c == '"' || c == '\\')
        escaped += '\\';
      escaped += (c == '\n') ? ' ' : c;
    }
    return raw(key, "\"" + escaped + "\"");
  }
  JsonObject& numbers(const std::string& key, const std::vector<double>& values)
  {
    std::ostringstream out;
    out.precision(6);
    out << '[';
    for (size_t i = 0; i < values.size(); ++i)
      out << (i ? "," : "") << values[i];
    out << ']';
    return raw(key, out.str());
  }
  JsonObject& raw(const std::string& key, const std::string& json)
  {
    body_ += (body_.empty() ? "" : ", ") + ("\"" + key + "\": ") + json;
    return *this;
  }
  std::string str() const { return "{" + body_ + "}"; }
  void print() const
  {
    std::printf("%s\n", str().c_str());
    std::fflush(stdout);
  }

private:
  std::string body_;
};

/// The "--name value" options of a benchmark program, each written into the field it names.
/// parse() is false on an unknown name or a name without its value, and says which on stderr.
class OptionParser
{
public:
  OptionParser& add(const char* name, std::string* field)
  {
    setters_.push_back({ name, [field](const char* value) {
                          *field = value;
                        } });
    return *this;
  }
  OptionParser& add(const char* name, double* field)
  {
    setters_.push_back({ name, [field](const char* value) {
                          *field = std::atof(value);
                        } });
    return *this;
  }
  OptionParser& add(const char* name, int* field)
  {
    setters_.push_back({ name, [field](const char* value) {
                          *field = std::atoi(value);
                        } });
    return *this;
  }
  bool parse(int argc, char** argv) const
  {
    for (int i = 1; i < argc; i += 2)
    {
      const auto setter = std::find_if(
        setters_.begin(), setters_.end(), [&](const Setter& s) { return s.name == argv[i]; });
      if (setter == setters_.end() || i + 1 == argc)
      {
        std::fprintf(stderr, "%s: %s '%s'\n", argv[0],
          setter == setters_.end() ? "unknown option" : "no value for option", argv[i]);
        return false;
      }
      setter->set(argv[i + 1]);
    }
    return true;
  }

private:
  struct Setter
  {
    std::string name;
    std::function<void(const char*)> set;
  };
  std::vector<Setter> setters_;
};

/// The senders' loop (bench_publish, bare_publish): `rate * seconds` calls of `publish` on an
/// absolute schedule with sleeps only (two cores: the receiver needs one), each timed, while
/// `keep_going()` holds; then half a second for a reliable writer's last samples, and the JSON
/// {"sent", "seconds", "rate", "publish_ms"} on stdout. `publish` returns whether it sent.
template<typename Publish, typename KeepGoing>
void publish_paced(double rate, double seconds, Publish publish, KeepGoing keep_going)
{
  std::vector<double> publish_ms;
  const int total = static_cast<int>(rate * seconds + 0.5);
  publish_ms.reserve(static_cast<size_t>(std::max(total, 0)));
  const auto period = std::chrono::duration<double>(1.0 / rate);
  const auto start = Clock::now();
  int sent = 0;
  for (int i = 0; i < total && keep_going(); ++i)
  {
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(period * i));
    const auto before = Clock::now();
    sent += publish() ? 1 : 0;
    publish_ms.push_back(ms_between(before, Clock::now()));
  }
  const double elapsed = ms_between(start, Clock::now()) / 1000.0;
  std::this_thread::sleep_for(std::chrono::milliseconds(500)); // reliable: let the last ones go out
  JsonObject()
    .number("sent", sent)
    .number("seconds", elapsed)
    .number("rate", elapsed > 0 ? sent / elapsed : 0.0)
    .numbers("publish_ms", publish_ms)
    .print();
}

} // namespace bench

#endif
