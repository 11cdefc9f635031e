// ros2vtk — our topic/service name expansion (wire::expand_topic_name, what
// Participant::resolve_name and so every publisher, subscription, service and client use) against
// rclpy's own, row by row. The expected column comes from rclpy at test time (rclpy_names_table.py
// run by the venv python), never from our code: a valid name must expand identically, an invalid
// one be refused by both.
#include "ros2vtk/wire/Names.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

struct Row
{
  std::string ns, name, status, result;
};

std::vector<std::string> split_tabs(const std::string& line)
{
  std::vector<std::string> fields;
  size_t start = 0;
  for (size_t tab = line.find('\t'); tab != std::string::npos; tab = line.find('\t', start))
  {
    fields.push_back(line.substr(start, tab - start));
    start = tab + 1;
  }
  fields.push_back(line.substr(start));
  return fields;
}

std::vector<Row> rclpy_table(std::string& failure)
{
  const std::string command =
    std::string("\"") + ROS2VTK_VENV_PYTHON + "\" \"" + ROS2VTK_RCLPY_NAMES_TABLE + "\"";
  std::vector<Row> rows;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    failure = "cannot run " + command;
    return rows;
  }
  std::string output;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
  {
    output.append(buffer, n);
  }
  const int status = pclose(pipe);
  if (status != 0)
  {
    failure = command + " exited with " + std::to_string(status);
    return rows;
  }
  size_t start = 0;
  for (size_t end = output.find('\n'); end != std::string::npos; end = output.find('\n', start))
  {
    const std::vector<std::string> fields = split_tabs(output.substr(start, end - start));
    start = end + 1;
    if (fields.size() != 4)
    {
      failure = "malformed line from rclpy: " + output.substr(0, 200);
      return {};
    }
    rows.push_back({ fields[0], fields[1], fields[2], fields[3] });
  }
  return rows;
}

TEST(NamesVsRclpy, EveryNameExpandsOrIsRefusedAsRclpyDoes)
{
  std::string failure;
  const std::vector<Row> rows = rclpy_table(failure);
  ASSERT_TRUE(failure.empty()) << failure;
  std::map<std::string, int> rows_per_namespace;
  int valid = 0;
  int invalid = 0;
  for (const Row& row : rows)
  {
    ++rows_per_namespace[row.ns];
    std::string expanded;
    std::string error;
    const bool ok = ros2vtk::wire::expand_topic_name(row.name, "talker", row.ns, expanded, &error);
    const std::string where = "name '" + row.name + "' in namespace '" + row.ns + "'";
    if (row.status == "ok")
    {
      ++valid;
      EXPECT_TRUE(ok) << where << ": rclpy expands it to '" << row.result
                      << "', we refuse: " << error;
      if (ok)
      {
        EXPECT_EQ(expanded, row.result) << where;
      }
    }
    else
    {
      ++invalid;
      EXPECT_FALSE(ok) << where << ": rclpy refuses it (" << row.result << "), we expand to '"
                       << expanded << "'";
      if (!ok)
      {
        EXPECT_FALSE(error.empty()) << where << ": refused without a message";
      }
    }
  }
  // The table really covers both namespaces and both outcomes (guards a broken rclpy run).
  EXPECT_GE(rows_per_namespace["/"], 25);
  EXPECT_GE(rows_per_namespace["/a/b"], 25);
  EXPECT_GE(valid, 25);
  EXPECT_GE(invalid, 25);
}

} // namespace
