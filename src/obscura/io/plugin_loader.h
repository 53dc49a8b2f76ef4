// Finds and loads Obscura's plugins: shared objects that hold what only some runs need and that
// bring heavy libraries with them (the image codecs: OpenImageIO; the MPI team: Open MPI), so
// that a process pays for loading them only when it uses them.
#pragma once

#include <string>
#include <vector>

namespace obscura {

// Where plugins are looked for: $OBSCURA_PLUGIN_DIR alone when it is set; otherwise, in order, the
// folder of the binary that holds this library (the executable, or the Python extension module),
// that folder's ../<install lib dir> (the installed layout: bin/obscura finds lib/…), and the
// build tree the library was built in.
std::vector<std::string> plugin_search_dirs();

// Loads `file` (e.g. "libobscura_image_codecs.so") from the first folder of plugin_search_dirs()
// that holds a loadable copy exporting `entry_point`, and returns that function's address. The
// plugin stays loaded for the life of the process. Throws obscura::Error naming every place it
// looked and why each failed, and the variable that names another folder.
void* load_plugin_entry(const std::string& file, const std::string& entry_point,
                        const std::string& needed_for);

}  // namespace obscura
