// What the OBJ, PLY and STL readers share: a bounded whole-file read, number parsing on a memory
// buffer (std::from_chars, no streams), and the one-mesh scene PLY and STL produce.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "obscura/scene/scene.h"

namespace obscura {

// The largest OBJ, MTL, PLY or STL file read (1 GiB, as for glTF): far beyond any mesh a render
// needs, and small enough that the decoded scene stays within a few GiB.
inline constexpr uint64_t kMaxMeshFileBytes = uint64_t(1) << 30;

// Throws obscura::Error naming `path` unless it is a regular file (not a FIFO, device or
// directory) of at most kMaxMeshFileBytes; returns its size.
uint64_t check_mesh_file(const std::string& path);

// The most triangles one mesh of an OBJ or PLY file may have (2^26, 67 M; 0.8 GB of indices).
// A file under kMaxMeshFileBytes holding real geometry stays below it; the cap stops a file of
// long polygons of repeated indices ("f 1 1 1 1 …") from turning each byte into six of memory.
inline constexpr size_t kMaxMeshTriangles = size_t(1) << 26;

// A whole file, if it is a regular file (not a FIFO, device or directory) of at most
// kMaxMeshFileBytes; else obscura::Error naming it. An empty file is returned empty.
std::vector<char> read_mesh_file(const std::string& path);

// A cursor over one line (or any range) of text: tokens are separated by spaces and tabs.
struct TextCursor {
  const char* p;
  const char* end;

  void skip_blanks() {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
  }
  bool at_end() {
    skip_blanks();
    return p >= end;
  }
  // The next token, empty at the end.
  std::string_view token();
  // The rest, with leading and trailing blanks removed.
  std::string_view rest();
  // A decimal number ("1", "-2.5e3", "+4", "nan", "inf"); false (cursor unmoved) if none.
  bool number(float& out);
  bool number(double& out);
  // A decimal integer; false (cursor unmoved) if none or out of range.
  bool integer(int64_t& out);
};

// The next line of `text` starting at `offset` (without its '\n' or "\r\n"); advances `offset`
// past it. `line_number` counts lines from 1.
struct LineReader {
  std::string_view text;
  size_t offset = 0;
  size_t line_number = 0;

  bool next(std::string_view& line);
};

// The file's stem ("bunny" for "dir/bunny.ply"), the name Scene::name takes.
std::string scene_name_of(const std::string& path);

// A scene with `mesh` as its only mesh, one instance in place, and `material` (PLY and STL
// bring no materials of their own).
Scene single_mesh_scene(const std::string& path, Mesh mesh, Material material);

// Appends the triangles of a polygon whose corners are mesh vertex indices. A quad is split from
// its reflex corner, where it has one, so that a concave quad is covered rather than overdrawn
// (the diagonal Assimp chose too); larger polygons are fanned from the first corner. Fewer than
// three corners (a point or a line) add nothing. Returns false, adding nothing, when the polygon
// would take `indices` past kMaxMeshTriangles triangles.
[[nodiscard]] bool triangulate_polygon(std::span<const uint32_t> corners,
                                       const std::vector<Point3f>& positions,
                                       std::vector<uint32_t>& indices);

// Keeps only the vertices some triangle uses, in their order, and renumbers the indices (a
// mesh file's unused vertices are not rendered; Assimp, whose output these loaders match, drops
// them too).
void drop_unused_vertices(Mesh& mesh);

}  // namespace obscura
