// The text of a `drm render` picture: a title line across the top and, when
// faces are coloured by something, a legend in the bottom-left corner
// (swatch, name, share of faces). Drawn with QPainter; the mesh is fitted to
// the space they leave free so that nothing covers it, except in pictures
// too narrow for that, where the legend covers a corner of the mesh (and in
// pictures too small for the legend it is left out).
#ifndef DRM_TOOLS_RENDER_LEGEND_H
#define DRM_TOOLS_RENDER_LEGEND_H

#include "picture.h"

#include <QFont>
#include <QImage>
#include <QRect>

#include <string>
#include <vector>

namespace drm {
namespace render {

class Annotations {
public:
    // Lays the text out for a width x height picture.
    Annotations(int width, int height, const std::string& title, const std::vector<LegendEntry>& legend);

    // Where the mesh goes: below the title, right of the legend's column.
    QRect meshArea() const { return meshArea_; }

    // Paints the title and the legend over `image`. Swatches are filled with
    // the entries' exact colours, unshaded and unblended, so the picture can
    // be read back to check which colours it uses.
    void draw(QImage& image) const;

private:
    QFont font_;
    int unit_;  // the text height in pixels; every gap is a fraction of it
    std::string title_;
    std::vector<LegendEntry> legend_;
    QRect titleRect_, legendRect_, meshArea_;
};

}  // namespace render
}  // namespace drm

#endif  // DRM_TOOLS_RENDER_LEGEND_H
