// Title and legend layout and painting (see legend.h).
#include "legend.h"

#include <QColor>
#include <QFontMetrics>
#include <QPainter>
#include <QString>

#include <algorithm>
#include <cmath>

namespace drm {
namespace render {

namespace {

// One decimal; a bucket with a few faces (a mesh's one start triangle) says
// so rather than showing 0.0 %.
QString shareText(double share) {
    if (share > 0 && share < 0.0005) return "< 0.1 %";
    return QString::number(100.0 * share, 'f', 1) + " %";
}

QColor qColour(Rgb c) { return QColor(c.r, c.g, c.b); }

}  // namespace

Annotations::Annotations(int width, int height, const std::string& title, const std::vector<LegendEntry>& legend)
    : unit_(std::max(9, std::min(width, height) / 40)), title_(title), legend_(legend) {
    font_.setFamily("DejaVu Sans");
    font_.setStyleHint(QFont::SansSerif);
    font_.setPixelSize(unit_);
    const QFontMetrics metrics(font_);
    const int pad = std::max(3, unit_ / 2);
    const int line = metrics.height();

    titleRect_ = QRect(pad, pad, width - 2 * pad, line);
    const int top = titleRect_.bottom() + pad;
    meshArea_ = QRect(0, top, width, height - top);
    if (legend_.empty()) return;

    // One row per entry: swatch, name, share right-aligned in its own column.
    int nameWidth = 0, shareWidth = metrics.horizontalAdvance(shareText(1.0));
    for (const LegendEntry& entry : legend_) {
        nameWidth = std::max(nameWidth, metrics.horizontalAdvance(QString::fromStdString(entry.label)));
        shareWidth = std::max(shareWidth, metrics.horizontalAdvance(shareText(entry.share)));
    }
    const int rowHeight = std::max(line, unit_) + pad / 2;
    const int boxWidth = pad + unit_ + pad + nameWidth + 2 * pad + shareWidth + pad;
    const int boxHeight = pad + int(legend_.size()) * rowHeight + pad / 2;
    if (boxHeight > meshArea_.height() - pad || boxWidth > width - 2 * pad) {
        legend_.clear();  // a legend cut in half would mislead; tiny pictures go without
        return;
    }
    legendRect_ = QRect(pad, height - pad - boxHeight, boxWidth, boxHeight);
    // Beside the mesh when that leaves it most of the width, over it otherwise.
    if (width - legendRect_.right() - pad >= width / 2) meshArea_.setLeft(legendRect_.right() + pad);
}

void Annotations::draw(QImage& image) const {
    QPainter painter(&image);
    painter.setFont(font_);
    const QFontMetrics metrics(font_);
    painter.setPen(QColor(30, 30, 30));
    painter.drawText(titleRect_, Qt::AlignLeft | Qt::AlignVCenter,
                     metrics.elidedText(QString::fromStdString(title_), Qt::ElideRight, titleRect_.width()));
    if (legend_.empty()) return;

    const int pad = std::max(3, unit_ / 2);
    painter.setPen(QColor(150, 150, 150));
    painter.setBrush(QColor(255, 255, 255));
    painter.drawRect(legendRect_.adjusted(0, 0, -1, -1));
    const int rowHeight = std::max(metrics.height(), unit_) + pad / 2;
    const int shareRight = legendRect_.right() - pad;
    for (size_t i = 0; i < legend_.size(); ++i) {
        const int rowTop = legendRect_.top() + pad + int(i) * rowHeight;
        const QRect swatch(legendRect_.left() + pad, rowTop + (rowHeight - pad / 2 - unit_) / 2, unit_, unit_);
        // A thin dark frame around the swatch, outside it, so pale colours
        // stand out from the white box while the swatch keeps its exact colour.
        painter.fillRect(swatch.adjusted(-1, -1, 1, 1), QColor(90, 90, 90));
        painter.fillRect(swatch, qColour(legend_[i].colour));
        painter.setPen(QColor(30, 30, 30));
        const QRect text(swatch.right() + 1 + pad, rowTop, shareRight - swatch.right() - pad, rowHeight - pad / 2);
        painter.drawText(text, Qt::AlignLeft | Qt::AlignVCenter, QString::fromStdString(legend_[i].label));
        painter.drawText(text, Qt::AlignRight | Qt::AlignVCenter, shareText(legend_[i].share));
    }
}

}  // namespace render
}  // namespace drm
