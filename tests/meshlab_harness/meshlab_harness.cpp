// Drives drm's MeshLab plugins through MeshLab's own PluginManager and
// load/save functions (common/utilities/load_save.h), the way PyMeshLab and
// the GUI do, with an offscreen Qt application and no display.
//
//   meshlab_harness PLUGIN_DIR info
//   meshlab_harness PLUGIN_DIR convert IN OUT [MASK] [NAME=VALUE...]
//   meshlab_harness PLUGIN_DIR colorize IN OUT [NAME=VALUE...]
//
// PLUGIN_DIR holds libio_drm.so and libfilter_drm.so; MeshLab's stock
// io_base plugin (PLY, OBJ, OFF, STL) is loaded from the installed MeshLab.
// convert opens IN with the plugin for its extension (as File > Import Mesh
// does: textures loaded, normals computed) and saves OUT with the export
// MASK (a number, "default": the plugin's default ticks, or "all": every box
// it offers) and the save parameters given. colorize opens IN, runs
// "Colorize Faces by Distance Rank" with the parameters given, and saves OUT
// with face colour and quality. Every line of MeshLab's log is printed as
// "log: LEVEL: TEXT", the save's warnings as "warning: TEXT"; a failure
// prints "error: MESSAGE" and exits 1.
#include <common/globals.h>
#include <common/mlexception.h>
#include <common/ml_document/mesh_document.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/interfaces/filter_plugin.h>
#include <common/plugins/interfaces/io_plugin.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

const char* const kStockPluginFolder = "/usr/lib/x86_64-linux-gnu/meshlab/plugins";

[[noreturn]] void die(const QString& message) {
    std::printf("error: %s\n", message.toUtf8().constData());
    std::exit(1);
}

void printLog(GLLogStream& log) {
    static const char* const levels[] = {"system", "warning", "filter", "debug"};
    for (const auto& entry : log.logStringList()) {
        const int level = entry.first;
        std::printf("log: %s: %s\n", level >= 0 && level < 4 ? levels[level] : "other",
                    entry.second.toUtf8().constData());
    }
    log.clear();
}

MeshLabPlugin* loadPlugin(const QString& path) {
    try {
        return meshlab::pluginManagerInstance().loadPlugin(path);
    } catch (const MLException& e) {
        die("cannot load " + path + ": " + e.what());
    }
}

// NAME=VALUE arguments into `parameters`: ints, bools (true/false) and enum
// indices, by the type of the parameter already there.
void setParameters(RichParameterList& parameters, char** first, char** last) {
    for (char** arg = first; arg != last; ++arg) {
        const QString text = QString::fromUtf8(*arg);
        const int equals = text.indexOf('=');
        if (equals <= 0) die("expected NAME=VALUE, not " + text);
        const QString name = text.left(equals), value = text.mid(equals + 1);
        auto it = parameters.findParameter(name);
        if (it == parameters.end()) die("no parameter named " + name);
        if (it->value().isBool())
            parameters.setValue(name, BoolValue(value == "true"));
        else if (it->value().isInt())
            parameters.setValue(name, IntValue(value.toInt()));
        else
            die("parameter " + name + " is of a type this harness does not set");
    }
}

int exportMask(IOPlugin& plugin, const QString& extension, const char* text) {
    int capability = 0, defaultBits = 0;
    plugin.exportMaskCapability(extension, capability, defaultBits);
    const std::string mask = text;
    if (mask == "default") return defaultBits;
    if (mask == "all") return capability;
    return std::atoi(text);
}

MeshModel& open(MeshDocument& md, const QString& fileName) {
    try {
        std::list<MeshModel*> meshes = meshlab::loadMeshWithStandardParameters(fileName, md);
        printLog(md.Log);
        return *meshes.front();
    } catch (const MLException& e) {
        printLog(md.Log);
        die(e.what());
    }
}

void save(MeshDocument& md, MeshModel& m, const QString& fileName, int mask, char** first, char** last) {
    const QString extension = QFileInfo(fileName).suffix().toLower();
    IOPlugin* plugin = meshlab::pluginManagerInstance().outputMeshPlugin(extension);
    if (plugin == nullptr) die("no plugin saves ." + extension);
    plugin->setLog(&md.Log);
    RichParameterList parameters = plugin->initSaveParameter(extension, m);
    setParameters(parameters, first, last);
    try {
        plugin->save(extension, fileName, m, mask, parameters, nullptr);
    } catch (const MLException& e) {
        printLog(md.Log);
        die(e.what());
    }
    printLog(md.Log);
    for (const QString& warning : plugin->warningMessageString().split('\n', Qt::SkipEmptyParts))
        std::printf("warning: %s\n", warning.toUtf8().constData());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) die("usage: meshlab_harness PLUGIN_DIR info|convert|colorize ...");
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const QString pluginDir = QString::fromUtf8(argv[1]);
    const std::string command = argv[2];

    loadPlugin(QString(kStockPluginFolder) + "/libio_base.so");
    MeshLabPlugin* io = loadPlugin(pluginDir + "/libio_drm.so");
    MeshLabPlugin* filter = loadPlugin(pluginDir + "/libfilter_drm.so");
    IOPlugin* ioPlugin = dynamic_cast<IOPlugin*>(io);
    FilterPlugin* filterPlugin = dynamic_cast<FilterPlugin*>(filter);
    if (ioPlugin == nullptr) die("libio_drm.so is not an IO plugin");
    if (filterPlugin == nullptr) die("libfilter_drm.so is not a filter plugin");
    if (meshlab::pluginManagerInstance().inputMeshPlugin("drm") != ioPlugin ||
        meshlab::pluginManagerInstance().outputMeshPlugin("drm") != ioPlugin)
        die("MeshLab does not give .drm files to libio_drm.so");

    if (command == "info") {
        std::printf("meshlab: %s\n", meshlab::meshlabVersion().c_str());
        std::printf("vendor: %s\n", io->vendor().toUtf8().constData());
        std::printf("io: %s:", io->pluginName().toUtf8().constData());
        for (const FileFormat& format : ioPlugin->importFormats())
            std::printf(" open %s (%s)", format.extensions.join(",").toUtf8().constData(),
                        format.description.toUtf8().constData());
        for (const FileFormat& format : ioPlugin->exportFormats())
            std::printf(" save %s", format.extensions.join(",").toUtf8().constData());
        std::printf("\nfilter: %s:", filter->pluginName().toUtf8().constData());
        for (QAction* action : filterPlugin->actions())
            std::printf(" \"%s\" (python: %s, class %d)", filterPlugin->filterName(action).toUtf8().constData(),
                        filterPlugin->pythonFilterName(action).toUtf8().constData(),
                        int(filterPlugin->getClass(action)));
        std::printf("\n");
        return 0;
    }

    MeshDocument md;
    if (command == "convert") {
        if (argc < 5) die("usage: meshlab_harness PLUGIN_DIR convert IN OUT [MASK] [NAME=VALUE...]");
        MeshModel& m = open(md, QString::fromUtf8(argv[3]));
        const QString out = QString::fromUtf8(argv[4]);
        IOPlugin* saver = meshlab::pluginManagerInstance().outputMeshPlugin(QFileInfo(out).suffix().toLower());
        if (saver == nullptr) die("no plugin saves " + out);
        const bool hasMask = argc > 5 && QString(argv[5]).indexOf('=') < 0;
        const int mask = exportMask(*saver, QFileInfo(out).suffix().toLower(), hasMask ? argv[5] : "default");
        std::printf("mesh: %d vertices, %d faces; mask %d\n", m.cm.vn, m.cm.fn, mask);
        save(md, m, out, mask, argv + (hasMask ? 6 : 5), argv + argc);
        return 0;
    }
    if (command == "colorize") {
        if (argc < 5) die("usage: meshlab_harness PLUGIN_DIR colorize IN OUT [NAME=VALUE...]");
        MeshModel& m = open(md, QString::fromUtf8(argv[3]));
        QAction* action = filterPlugin->actions().front();
        filterPlugin->setLog(&md.Log);
        RichParameterList parameters = filterPlugin->initParameterList(action, md);
        setParameters(parameters, argv + 5, argv + argc);
        m.updateDataMask(filterPlugin->getRequirements(action));
        unsigned int postConditionMask = 0;
        try {
            filterPlugin->applyFilter(action, parameters, md, postConditionMask, nullptr);
        } catch (const MLException& e) {
            printLog(md.Log);
            die(e.what());
        }
        printLog(md.Log);
        std::printf("post-condition: %u\n", postConditionMask);
        save(md, m, QString::fromUtf8(argv[4]),
             vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX |
                 vcg::tri::io::Mask::IOM_FACECOLOR | vcg::tri::io::Mask::IOM_FACEQUALITY,
             argv + argc, argv + argc);
        return 0;
    }
    die("unknown command " + QString::fromStdString(command));
}
