// ros2vtk — unit tests of ParameterStore: rclcpp's parameter service semantics (WIRE_NOTES
// §5.3: per-item and atomic sets, type rules, read-only, ranges, listing by prefix and depth,
// events) and the bound on the size of values other nodes may set (issue 11 item 12).
#include "ros2vtk/wire/ParameterStore.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using namespace ros2vtk::wire;

// rcl_interfaces/msg/ParameterType constants.
constexpr uint8_t kInteger = 2, kDouble = 3, kString = 4, kIntegerArray = 7, kStringArray = 9;

rcl::ParameterValue integer(int64_t v)
{
  rcl::ParameterValue value;
  value.type = kInteger;
  value.integer_value = v;
  return value;
}

rcl::ParameterValue real(double v)
{
  rcl::ParameterValue value;
  value.type = kDouble;
  value.double_value = v;
  return value;
}

rcl::ParameterValue text(const std::string& v)
{
  rcl::ParameterValue value;
  value.type = kString;
  value.string_value = v;
  return value;
}

rcl::Parameter parameter(const std::string& name, const rcl::ParameterValue& value)
{
  rcl::Parameter p;
  p.name = name;
  p.value = value;
  return p;
}

TEST(ParameterStore, DeclareGetAndTypes)
{
  ParameterStore store;
  std::string error;
  ASSERT_TRUE(store.declare("gain", real(0.5), &error));
  EXPECT_FALSE(store.declare("gain", real(1.0), &error)); // declared twice
  EXPECT_FALSE(error.empty());
  ASSERT_TRUE(store.declare("frame", text("ct"), &error));
  const auto values = store.get_parameters({ "frame", "gain" });
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0].string_value, "ct");
  EXPECT_EQ(values[1].double_value, 0.5);
  EXPECT_EQ(
    store.get_parameter_types({ "gain", "frame" }), (std::vector<uint8_t>{ kDouble, kString }));
  // rclcpp answers an empty list when any name is undeclared.
  EXPECT_TRUE(store.get_parameters({ "gain", "missing" }).empty());
  EXPECT_TRUE(store.get_parameter_types({ "missing" }).empty());
  EXPECT_TRUE(store.describe_parameters({ "missing" }).empty());
}

TEST(ParameterStore, SetParametersIsPerItem)
{
  ParameterStore store;
  ASSERT_TRUE(store.declare("count", integer(1), nullptr));
  const auto results = store.set_parameters({ parameter("count", integer(2)),
    parameter("count", text("two")), parameter("nope", integer(3)) });
  ASSERT_EQ(results.size(), 3u);
  EXPECT_TRUE(results[0].successful);
  EXPECT_TRUE(results[0].reason.empty());
  EXPECT_FALSE(results[1].successful); // static typing: integer stays integer
  EXPECT_NE(results[1].reason.find("Wrong parameter type"), std::string::npos) << results[1].reason;
  EXPECT_FALSE(results[2].successful); // undeclared
  EXPECT_EQ(store.get("count")->integer_value, 2);
}

TEST(ParameterStore, SetAtomicallyIsAllOrNothing)
{
  ParameterStore store;
  ASSERT_TRUE(store.declare("a", integer(1), nullptr));
  ASSERT_TRUE(store.declare("b", integer(1), nullptr));
  auto result =
    store.set_parameters_atomically({ parameter("a", integer(5)), parameter("b", text("x")) });
  EXPECT_FALSE(result.successful);
  EXPECT_EQ(store.get("a")->integer_value, 1); // nothing applied
  result =
    store.set_parameters_atomically({ parameter("a", integer(5)), parameter("c", integer(1)) });
  EXPECT_FALSE(result.successful);
  EXPECT_EQ(result.reason, "One or more parameters were not declared before setting");
  result =
    store.set_parameters_atomically({ parameter("a", integer(5)), parameter("b", integer(6)) });
  EXPECT_TRUE(result.successful);
  EXPECT_EQ(store.get("a")->integer_value, 5);
  EXPECT_EQ(store.get("b")->integer_value, 6);
}

TEST(ParameterStore, ReadOnlyAndRanges)
{
  ParameterStore store;
  rcl::ParameterDescriptor read_only;
  read_only.read_only = true;
  ASSERT_TRUE(store.declare("fixed", integer(1), read_only, nullptr));
  rcl::ParameterDescriptor ranged;
  rcl::IntegerRange range;
  range.from_value = 0;
  range.to_value = 10;
  range.step = 2;
  ranged.integer_range.push_back(range);
  ASSERT_TRUE(store.declare("even", integer(0), ranged, nullptr));
  const auto results = store.set_parameters({ parameter("fixed", integer(2)),
    parameter("even", integer(4)), parameter("even", integer(5)), parameter("even", integer(12)) });
  EXPECT_FALSE(results[0].successful);
  EXPECT_NE(results[0].reason.find("read-only"), std::string::npos);
  EXPECT_TRUE(results[1].successful);
  EXPECT_FALSE(results[2].successful); // off the step
  EXPECT_FALSE(results[3].successful); // above the range
  EXPECT_EQ(store.get("even")->integer_value, 4);
}

TEST(ParameterStore, ValidatorCanRefuseWithItsReason)
{
  ParameterStore store;
  ASSERT_TRUE(store.declare("mode", text("auto"), nullptr));
  store.set_validator([](const rcl::Parameter& p) {
    return p.value.string_value == "manual" || p.value.string_value == "auto" ? std::string()
                                                                              : "unknown mode";
  });
  const auto results =
    store.set_parameters({ parameter("mode", text("manual")), parameter("mode", text("x")) });
  EXPECT_TRUE(results[0].successful);
  EXPECT_EQ(results[1].reason, "unknown mode");
  EXPECT_EQ(store.get("mode")->string_value, "manual");
}

TEST(ParameterStore, PostSetCallbacksSeeEverySuccessfulSetAndNothingElse)
{
  // How a node follows its own use_sim_time: whatever path the set takes (its own API or the
  // services), callbacks see the applied values, and refused or undeclared ones not at all.
  ParameterStore store;
  ASSERT_TRUE(store.declare("count", integer(1), nullptr));
  ASSERT_TRUE(store.declare("other", integer(1), nullptr));
  std::vector<std::string> seen;
  const size_t id = store.add_post_set_callback([&](const std::vector<rcl::Parameter>& changed) {
    std::string batch;
    for (const auto& p : changed)
      batch += p.name + "=" + std::to_string(p.value.integer_value) + " ";
    seen.push_back(batch);
  });
  ASSERT_TRUE(store.declare("late", integer(7), nullptr)); // a declaration is not a set
  store.set_parameters({ parameter("count", integer(2)), parameter("count", text("x")),
    parameter("nope", integer(3)) });
  store.set_parameters_atomically(
    { parameter("count", integer(4)), parameter("other", integer(5)) });
  store.set_parameters_atomically(
    { parameter("count", integer(6)), parameter("other", text("y")) }); // refused
  EXPECT_EQ(seen, (std::vector<std::string>{ "count=2 ", "count=4 other=5 " }));
  store.remove_post_set_callback(id);
  store.set_parameters({ parameter("count", integer(8)) });
  EXPECT_EQ(seen.size(), 2u);
}

TEST(ParameterStore, ListByPrefixAndDepth)
{
  ParameterStore store;
  for (const char* name : { "a", "b.c", "b.d.e", "f.g" })
    ASSERT_TRUE(store.declare(name, integer(0), nullptr));
  auto names = [](const rcl::ListParametersResult& r) {
    return r.names;
  };
  auto all = store.list_parameters({}, 0);
  EXPECT_EQ(all.names.size(), 4u);
  // depth 1 with no prefix: names with fewer than 1 dot.
  EXPECT_EQ(names(store.list_parameters({}, 1)), std::vector<std::string>{ "a" });
  // prefix "b", depth 1: "b.c" only (the remainder "d.e" has a dot).
  EXPECT_EQ(names(store.list_parameters({ "b" }, 1)), std::vector<std::string>{ "b.c" });
  auto b_all = store.list_parameters({ "b" }, 0);
  EXPECT_EQ(b_all.names.size(), 2u);
  EXPECT_NE(std::find(b_all.prefixes.begin(), b_all.prefixes.end(), "b.d"), b_all.prefixes.end());
}

TEST(ParameterStore, EventsForDeclareSetUndeclare)
{
  ParameterStore store;
  ASSERT_TRUE(store.declare("x", integer(1), nullptr));
  store.set_parameters({ parameter("x", integer(2)), parameter("x", text("bad")) });
  ASSERT_TRUE(store.undeclare("x", nullptr));
  const auto events = store.take_events();
  ASSERT_EQ(events.size(), 3u); // the refused set makes no event
  EXPECT_EQ(events[0].new_parameters.size(), 1u);
  ASSERT_EQ(events[1].changed_parameters.size(), 1u);
  EXPECT_EQ(events[1].changed_parameters[0].value.integer_value, 2);
  EXPECT_EQ(events[2].deleted_parameters.size(), 1u);
  EXPECT_TRUE(store.take_events().empty());
}

TEST(ParameterStore, ValueSizeCountsPayloadBytes)
{
  rcl::ParameterValue ints;
  ints.type = kIntegerArray;
  ints.integer_array_value.assign(3, 7);
  EXPECT_EQ(parameter_value_size(ints), 24u);
  rcl::ParameterValue strings;
  strings.type = kStringArray;
  strings.string_array_value = { "ab", "" };
  EXPECT_EQ(parameter_value_size(strings), 2u + 4u + 0u + 4u);
  EXPECT_EQ(parameter_value_size(text("hello")), 5u);
  EXPECT_EQ(parameter_value_size(integer(1 << 30)), 0u);
}

TEST(ParameterStore, OversizedValuesAreRefusedWithAReason)
{
  ParameterStore store;
  EXPECT_EQ(store.value_size_limit(), ParameterStore::kDefaultValueSizeLimit);
  ASSERT_TRUE(store.declare("frame", text("ct"), nullptr));
  store.set_value_size_limit(8);
  rcl::ParameterValue ints;
  ints.type = kIntegerArray;
  ints.integer_array_value.assign(2, 1);
  const auto results = store.set_parameters({ parameter("frame", text(std::string(8, 'x'))),
    parameter("frame", text(std::string(9, 'x'))), parameter("frame", ints) });
  EXPECT_TRUE(results[0].successful);
  EXPECT_FALSE(results[1].successful);
  EXPECT_EQ(results[1].reason,
    "parameter 'frame' cannot be set: its string value holds 9 bytes, more than this node accepts "
    "(8)");
  // Refused for its size before its type.
  EXPECT_FALSE(results[2].successful);
  EXPECT_NE(results[2].reason.find("integer_array value holds 16 bytes"), std::string::npos)
    << results[2].reason;
  EXPECT_EQ(store.get("frame")->string_value, std::string(8, 'x'));
  // The atomic set refuses too, with the same reason.
  const auto atomic =
    store.set_parameters_atomically({ parameter("frame", text(std::string(9, 'y'))) });
  EXPECT_FALSE(atomic.successful);
  EXPECT_EQ(atomic.reason, results[1].reason);
  // Our own declarations are not bounded.
  EXPECT_TRUE(store.declare("big", text(std::string(100, 'z')), nullptr));
}

} // namespace
