// MeshLab 2020.09 filter plugin: "Colorize Faces by Distance Rank" (Filters >
// Color Creation and Processing) colours each face by the distance rank code
// that created it, as `drm ranks` does and as in the paper's Figure 1, and
// logs what the connectivity costs.
#ifndef DRM_MESHLAB_FILTER_DRM_H
#define DRM_MESHLAB_FILTER_DRM_H

#include <common/interfaces.h>  // first: it includes GLEW before any GL header

#include <QObject>

#include <string>

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

#endif  // DRM_MESHLAB_FILTER_DRM_H
