#include "bridge/host.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMainWindow>
#include <QStatusBar>
#include <QStringList>

#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace drm_meshlab {

bool inMeshlabserver() {
    if (QCoreApplication::instance() == nullptr) return false;
    return QFileInfo(QCoreApplication::applicationFilePath()).fileName() == "meshlabserver";
}

void clearStatusBar() {
    if (qobject_cast<QApplication*>(QCoreApplication::instance()) == nullptr) return;
    for (QWidget* widget : QApplication::topLevelWidgets()) {
        QMainWindow* window = qobject_cast<QMainWindow*>(widget);
        if (window != nullptr && window->statusBar() != nullptr) window->statusBar()->clearMessage();
    }
}

std::string serverLogFile() {
    if (QCoreApplication::instance() == nullptr) return std::string();
    const QStringList arguments = QCoreApplication::arguments();
    const int at = arguments.indexOf("-l");
    if (at < 0 || at + 1 >= arguments.size()) return std::string();
    QString name = QDir::cleanPath(arguments[at + 1]);
    // Among the files this process has open, the one -l named: its absolute
    // name ends with the name as given (relative to the folder the server
    // started in, which it no longer is in).
    const QDir descriptors("/proc/self/fd");
    for (const QString& fd : descriptors.entryList(QDir::Files | QDir::System | QDir::NoDotAndDotDot)) {
        const QString open = QFileInfo(descriptors.filePath(fd)).symLinkTarget();
        if (open.isEmpty()) continue;
        if (QDir::isAbsolutePath(name) ? open == name : open.endsWith("/" + name))
            return QFile::encodeName(open).toStdString();
    }
    return std::string();
}

void printToServerOutput(const std::string& line) {
    if (!inMeshlabserver()) return;
    // Everything meshlabserver buffered goes out first, in both places.
    std::fflush(nullptr);
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
    const std::string log = serverLogFile();
    if (log.empty()) return;
    const int fd = ::open(log.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0) return;
    const std::string text = line + "\n";
    for (size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n <= 0) break;
        done += size_t(n);
    }
    ::close(fd);
}

}  // namespace drm_meshlab
