#pragma once
// Pictures of C-space and of what the cameras saw, for the demo's report. Private to the CLI.
//
// A slice shows the cells of two joints with the other joints' cells held (at the robot's current
// cell): the paper's joint 1 x joint 2 view and others. Colours: forbidden red, static obstacle
// cells dark red, free white, the robot's cell green.

#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

// One slice over joints axis_x (across) x axis_y (down), each cell `scale` pixels, with a title
// and the joints named on the axes; `path` (cells the robot passed through, oldest first) is
// drawn over it as a line through the cells' centres in the slice's two joints. CV_8UC3.
cv::Mat forbidden_slice(const CspaceGrid& grid, const CellSet& forbidden,
                        const CellSet& static_cells, CellIndex robot_cell, std::uint32_t axis_x,
                        std::uint32_t axis_y, const std::string& title,
                        const std::vector<CellIndex>& path = {});

// A camera frame (CV_8UC1) with its feature cells tinted: the robot's silhouette blue, the
// obstacles after robot removal red, blocked cells that were removed as the robot yellow. CV_8UC3.
cv::Mat camera_overlay(const cv::Mat& frame, const FeatureMask& blocked, const FeatureMask& robot,
                       const FeatureMask& obstacles, const std::string& label);

}  // namespace safecell
