// MeshLab 2020.09 IO plugin for .drm files: File > Import Mesh opens them,
// File > Export Mesh As writes them with the codec options in the save
// dialog. A thin adapter: the codec does the work, drm_vcg converts meshes
// and writes files atomically, this class talks to MeshLab.
#ifndef DRM_MESHLAB_IO_DRM_H
#define DRM_MESHLAB_IO_DRM_H

#include <common/interfaces.h>  // first: it includes GLEW before any GL header

#include <QObject>

#include <string>

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
    // Logs LINE (the GUI's log pane) and, in meshlabserver, which shows no
    // IO plugin's log, prints it on stdout and into the -l log file.
    void report(const std::string& line);
};

#endif  // DRM_MESHLAB_IO_DRM_H
