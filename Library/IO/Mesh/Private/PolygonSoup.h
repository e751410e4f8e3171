// What the OBJ, PLY and OFF readers produce: the file's polygons as plain C++, before they become
// the kernel's triangles (PolygonsToTriangles.h). No VTK here, so that reading such a file loads
// no VTK library; only a file with polygons of more than three corners goes on to VTK's
// triangulation (VtkOnUse.h).
#pragma once

#include <cstdint>
#include <vector>

namespace proxima::detail
{

struct PolygonSoup
{
  /// x, y, z per point, in double.
  std::vector<double> points;
  /// Empty, or x, y, z per point.
  std::vector<double> normals;
  /// Empty, or u, v per point.
  std::vector<double> texCoords;
  /// The corners of every face of three or more corners, as point indices, face after face;
  /// face f is corners[faceStarts[f]] to corners[faceStarts[f + 1]] (faceStarts starts with 0).
  std::vector<std::int64_t> corners;
  std::vector<std::size_t> faceStarts{0};
  /// Cells that hold no surface, counted for the message of a file without triangles: lines
  /// (and polylines) and vertex cells (and poly-vertices).
  std::int64_t numLines = 0;
  std::int64_t numVertexCells = 0;

  std::int64_t numPoints() const { return static_cast<std::int64_t>(points.size() / 3); }
  std::int64_t numFaces() const { return static_cast<std::int64_t>(faceStarts.size()) - 1; }

  void addPoint(double x, double y, double z)
  {
    points.push_back(x);
    points.push_back(y);
    points.push_back(z);
  }
  /// A cell of `size` corners: a face from three on, else a line or a vertex cell.
  void addCell(const std::int64_t* ids, std::size_t size)
  {
    if (size >= 3)
    {
      corners.insert(corners.end(), ids, ids + size);
      faceStarts.push_back(corners.size());
    }
    else if (size == 2)
    {
      ++numLines;
    }
    else if (size == 1)
    {
      ++numVertexCells;
    }
  }
};

} // namespace proxima::detail
