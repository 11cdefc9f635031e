// A robot put into the scene the way examples/demo/demo.py's DemoRobot does it (until the C++
// vtkROS2RobotNode exists): one tf lookup node per link, from the root link, with the frame
// prefix, and one model node per visual under its link's transform. The geometry comes from
// ros2vtk::robot::RobotLoader (metres); model matrices scale it to the scene's millimetres.
#ifndef ros2vtk_bench_RobotScene_hpp
#define ros2vtk_bench_RobotScene_hpp

#include "ros2vtk/robot/RobotLoader.hpp"
#include "vtkROS2ModelNode.h"
#include "vtkROS2NodeNode.h"
#include "vtkROS2Scene.h"
#include "vtkROS2Tf2LookupNode.h"

#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace bench {

struct SceneRobot
{
  std::vector<vtkROS2Tf2LookupNode*> lookups; // owned by the scene
  size_t models = 0;

  /// Links whose lookup succeeded in the latest spin.
  size_t tracked() const
  {
    size_t ok = 0;
    for (auto* lookup : lookups)
      ok += std::string(lookup->GetLookupStatus()) == "ok" ? 1 : 0;
    return ok;
  }
};

inline SceneRobot add_robot_to_scene(vtkROS2NodeNode* node, vtkROS2Scene* scene,
                                     const ros2vtk::robot::RobotVisuals& robot, const std::string& prefix)
{
  SceneRobot added;
  const std::string fixed = prefix + robot.root_link;
  for (const auto& link : robot.links)
  {
    vtkROS2Tf2LookupNode* lookup = nullptr;
    if (link.link != robot.root_link)
    {
      lookup = node->CreateAndAddTf2LookupNode(fixed.c_str(), (prefix + link.link).c_str());
      if (lookup)
        added.lookups.push_back(lookup);
    }
    for (const auto& visual : link.visuals)
    {
      vtkNew<vtkROS2ModelNode> model;
      model->SetName((prefix + link.link + "_model").c_str());
      model->SetPolyData(visual.geometry);
      // Visual origin in metres -> millimetres: scale rotation (the geometry) and translation.
      vtkNew<vtkMatrix4x4> matrix;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
          matrix->SetElement(r, c, 1000.0 * visual.origin->GetElement(r, c));
      model->SetMatrixModelToParent(matrix);
      const auto color = visual.display_color();
      model->SetColor(color[0], color[1], color[2]);
      scene->AddNode(model);
      if (lookup)
        model->SetParentTransformNodeID(lookup->GetID());
      ++added.models;
    }
  }
  return added;
}

} // namespace bench

#endif
