// drm-png-probe FILE.png [--skip-top N] [RRGGBB...]: what cli_test.sh needs
// to know about a picture `drm render` wrote, printed one fact per line:
//
//   size W H
//   cracks N        background pixels (the top-left pixel's colour) below
//                   row N whose left and right, or upper and lower,
//                   neighbours are both something else: a one-pixel gap
//                   inside a surface, which a closed mesh must not have
//   RRGGBB COUNT    pixels of exactly that colour, for each colour asked
//
// Exit 1 (and a message) if FILE is not a readable image.
#include <QColor>
#include <QImage>
#include <QString>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: drm-png-probe FILE.png [--skip-top N] [RRGGBB...]\n");
        return 2;
    }
    QImage image;
    if (!image.load(QString::fromLocal8Bit(argv[1]), "PNG")) {
        std::fprintf(stderr, "drm-png-probe: %s is not a readable PNG\n", argv[1]);
        return 1;
    }
    image = image.convertToFormat(QImage::Format_RGB32);
    int skipTop = 0;
    std::vector<std::string> colours;
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--skip-top") == 0 && i + 1 < argc)
            skipTop = std::atoi(argv[++i]);
        else
            colours.push_back(argv[i]);
    }

    const int w = image.width(), h = image.height();
    std::printf("size %d %d\n", w, h);
    const QRgb background = image.pixel(0, 0);
    auto isBackground = [&](int x, int y) { return image.pixel(x, y) == background; };
    long cracks = 0;
    for (int y = std::max(1, skipTop); y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x)
            if (isBackground(x, y) && ((!isBackground(x - 1, y) && !isBackground(x + 1, y)) ||
                                       (!isBackground(x, y - 1) && !isBackground(x, y + 1))))
                ++cracks;
    std::printf("cracks %ld\n", cracks);
    for (const std::string& hex : colours) {
        const QRgb wanted = 0xff000000u | QRgb(std::strtoul(hex.c_str(), nullptr, 16));
        long count = 0;
        for (int y = 0; y < h; ++y) {
            const QRgb* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
            for (int x = 0; x < w; ++x) count += row[x] == wanted;
        }
        std::printf("%s %ld\n", hex.c_str(), count);
    }
    return 0;
}
