// Which MeshLab program the plugins run in, and the places it shows text.
//
// The GUI shows the log pane (HTML) and a status bar; meshlabserver prints
// a filter's log on stdout (or into its -l file) but neither an IO plugin's
// log nor its errorMessage, and prints progress labels as they come, with
// no separator.
#ifndef DRM_MESHLAB_HOST_H
#define DRM_MESHLAB_HOST_H

#include <string>

namespace drm_meshlab {

// True inside meshlabserver (the executable's name), false in the GUI.
bool inMeshlabserver();

// Empties the status bar of the application's main window, where MeshLab's
// progress callback leaves the last stage ("ranking") for seconds after the
// operation ended. Does nothing without a main window (meshlabserver).
void clearStatusBar();

// meshlabserver only: prints LINE on stdout and appends it to the log file
// given with -l, if any, after flushing what meshlabserver wrote there, so
// the IO plugin's words stand where they belong.
void printToServerOutput(const std::string& line);

// The file meshlabserver's -l names, as open in this process ("" if none):
// meshlabserver changes its working folder while it loads and saves, so the
// name is matched against its open files.
std::string serverLogFile();

}  // namespace drm_meshlab

#endif  // DRM_MESHLAB_HOST_H
