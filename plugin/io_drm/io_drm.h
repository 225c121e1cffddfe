// MeshLab IO plugin for .drm files: File > Import Mesh opens them, File >
// Export Mesh As writes them with the codec options in the save dialog. A
// thin adapter: the codec does the work, drm_vcg converts meshes and writes
// files atomically, io_drm_work.h holds what open and save do, and this class
// speaks the plugin API of the MeshLab it is built for (bridge/meshlab_api.h).
#ifndef DRM_MESHLAB_IO_DRM_H
#define DRM_MESHLAB_IO_DRM_H

#include "bridge/meshlab_api.h"  // first: MeshLab includes GLEW before any GL header

#include <QObject>

#include <string>

#if DRM_MESHLAB_API >= 2021

class DrmIOPlugin : public QObject, public IOPlugin {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(IO_PLUGIN_IID)
    Q_INTERFACES(IOPlugin)

public:
    QString pluginName() const override;
    QString vendor() const override;  // shown in Help > Plugin Info
    std::list<FileFormat> importFormats() const override;
    std::list<FileFormat> exportFormats() const override;
    void exportMaskCapability(const QString& format, int& capability, int& defaultBits) const override;
    RichParameterList initSaveParameter(const QString& format, const MeshModel& m) const override;

    // Both throw MLException with the sentence the user sees.
    void open(const QString& format, const QString& fileName, MeshModel& m, int& mask,
              const RichParameterList& parameters, vcg::CallBackPos* cb = nullptr) override;
    void save(const QString& format, const QString& fileName, MeshModel& m, const int mask,
              const RichParameterList& parameters, vcg::CallBackPos* cb = nullptr) override;

private:
    void logLine(GLLogStream::Levels level, const std::string& line) const;
};

#else

class DrmIOPlugin : public QObject, public MeshIOInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_IO_INTERFACE_IID)
    Q_INTERFACES(MeshIOInterface)

public:
    QString pluginName() const override;
    QList<Format> importFormats() const override;
    QList<Format> exportFormats() const override;
    void GetExportMaskCapability(QString& format, int& capability, int& defaultBits) const override;
    void initSaveParameter(const QString& format, MeshModel& m, RichParameterList& parameters) override;

    bool open(const QString& format, const QString& fileName, MeshModel& m, int& mask,
              const RichParameterList& parameters, vcg::CallBackPos* cb = nullptr,
              QWidget* parent = nullptr) override;
    bool save(const QString& format, const QString& fileName, MeshModel& m, const int mask,
              const RichParameterList& parameters, vcg::CallBackPos* cb = nullptr,
              QWidget* parent = nullptr) override;

private:
    // Sets errorMessage (MeshLab shows it in a dialog), logs it, and prints
    // it on stderr: meshlabserver prints neither errorMessage after a failed
    // -i open or save, nor the log of an IO plugin it did not open with.
    bool fail(const std::string& message);
    void logLine(GLLogStream::Levels level, const std::string& line);
};

#endif

#endif  // DRM_MESHLAB_IO_DRM_H
