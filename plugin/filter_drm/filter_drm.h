// MeshLab filter plugin: "Colorize Faces by Distance Rank" (Filters > Color
// Creation and Processing) colours each face by the distance rank code that
// created it, as `drm ranks` does and as in the paper's Figure 1, stores the
// rank as face quality, and logs what the connectivity costs with a legend of
// the colours. rank_colouring.h holds the work; this class speaks the plugin
// API of the MeshLab it is built for (bridge/meshlab_api.h).
#ifndef DRM_MESHLAB_FILTER_DRM_H
#define DRM_MESHLAB_FILTER_DRM_H

#include "bridge/meshlab_api.h"  // first: MeshLab includes GLEW before any GL header

#include <QObject>

#include <string>

#if DRM_MESHLAB_API >= 2021

class DrmFilterPlugin : public QObject, public FilterPlugin {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
    Q_INTERFACES(FilterPlugin)

public:
    enum { FP_RANK_COLOURS };

    DrmFilterPlugin();

    QString pluginName() const override;
    QString vendor() const override;  // shown in Help > Plugin Info
    QString filterName(ActionIDType filter) const override;
    QString pythonFilterName(ActionIDType filter) const override;
    QString filterInfo(ActionIDType filter) const override;
    FilterClass getClass(const QAction* action) const override;
    int getRequirements(const QAction* action) override;
    int getPreConditions(const QAction* action) const override;
    int postCondition(const QAction* action) const override;
    FilterArity filterArity(const QAction* action) const override;
    RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;
    // Throws MLException with the sentence the user sees.
    std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& parameters,
                                                MeshDocument& md, unsigned int& postConditionMask,
                                                vcg::CallBackPos* cb) override;
};

#else

class DrmFilterPlugin : public QObject, public MeshFilterInterface {
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum { FP_RANK_COLOURS };

    DrmFilterPlugin();

    QString pluginName() const override;
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction* action) override;
    int getRequirements(QAction* action) override;
    int getPreConditions(QAction* action) const override;
    int postCondition(QAction* action) const override;
    FILTER_ARITY filterArity(QAction* action) const override;
    void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parameters) override;
    bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& parameters,
                     vcg::CallBackPos* cb) override;

private:
    // Sets errorMessage and logs it: meshlabserver prints the log, not
    // errorMessage.
    bool fail(const std::string& message);
};

#endif

#endif  // DRM_MESHLAB_FILTER_DRM_H
