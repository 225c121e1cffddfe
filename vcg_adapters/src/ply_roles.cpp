// assignRoles (see ply_header.h): which of a header's properties fill which
// part of drm::Mesh, by the names MeshLab writes and reads (the list is in
// ply_reader.h), and which are named as dropped or as other properties and
// elements. A property takes one role at most, and of the name sets for one
// role the first an element has wins (red green blue, else diffuse_red
// diffuse_green diffuse_blue, else intensity).
#include "ply_header.h"

#include "drm_vcg/joined_list.h"

#include <initializer_list>

namespace drm {
namespace vcgio {
namespace ply {

namespace {

Property* scalarProperty(Element& element, const char* name) {
    for (Property& p : element.properties)
        if (!p.list && p.name == name && p.role == Role::Other) return &p;
    return nullptr;
}

Property* listProperty(Element& element, const char* name) {
    for (Property& p : element.properties)
        if (p.list && p.name == name && p.role == Role::Other) return &p;
    return nullptr;
}

// Gives the scalars `names` the role, as components 0, 1, ..., if the
// element has them all (and none has a role yet).
bool assignAll(Element& element, std::initializer_list<const char*> names, Role role) {
    std::vector<Property*> found;
    for (const char* name : names) {
        Property* p = scalarProperty(element, name);
        if (!p) return false;
        found.push_back(p);
    }
    for (size_t i = 0; i < found.size(); ++i) {
        found[i]->role = role;
        found[i]->component = i;
    }
    return true;
}

bool assignOne(Property* p, Role role, size_t component = 0) {
    if (!p) return false;
    p->role = role;
    p->component = component;
    return true;
}

}  // namespace

// What each property becomes; what is not kept goes into `out`'s lists.
void assignRoles(Header& header, PlyContents& out) {
    bool faceNormals = false, cornerColours = false, radii = false, edges = false, camera = false;
    for (Element& e : header.elements) {
        if (e.kind == Kind::Vertex) {
            const char* const axes[3] = {"x", "y", "z"};
            std::vector<std::string> missing;
            for (size_t k = 0; k < 3; ++k)
                if (!assignOne(scalarProperty(e, axes[k]), Role::Position, k)) missing.push_back(axes[k]);
            if (!missing.empty())
                throw invalid("the vertex element has no " + joinList(missing) + (missing.size() == 1 ? " property" : " properties"));
            assignAll(e, {"nx", "ny", "nz"}, Role::Normal);
            if (assignAll(e, {"red", "green", "blue"}, Role::Colour)) assignOne(scalarProperty(e, "alpha"), Role::Colour, 3);
            else if (assignAll(e, {"diffuse_red", "diffuse_green", "diffuse_blue"}, Role::Colour))
                assignOne(scalarProperty(e, "diffuse_alpha"), Role::Colour, 3);
            else assignOne(scalarProperty(e, "intensity"), Role::Grey);
            if (!assignOne(scalarProperty(e, "quality"), Role::Quality)) assignOne(scalarProperty(e, "confidence"), Role::Quality);
            if (!assignAll(e, {"texture_u", "texture_v"}, Role::TexCoord) && !assignAll(e, {"s", "t"}, Role::TexCoord))
                assignAll(e, {"u", "v"}, Role::TexCoord);
            radii = assignOne(scalarProperty(e, "radius"), Role::Dropped) && e.count > 0;
        } else if (e.kind == Kind::Face) {
            if (!assignOne(listProperty(e, "vertex_indices"), Role::Corners) && !assignOne(listProperty(e, "vertex_index"), Role::Corners))
                continue;  // no corners: nothing else on a face can be kept
            assignOne(listProperty(e, "texcoord"), Role::CornerTexCoords);
            assignOne(scalarProperty(e, "texnumber"), Role::TexNumber);
            if (assignAll(e, {"red", "green", "blue"}, Role::FaceColour)) assignOne(scalarProperty(e, "alpha"), Role::FaceColour, 3);
            assignOne(scalarProperty(e, "quality"), Role::FaceQuality);
            faceNormals = assignAll(e, {"nx", "ny", "nz"}, Role::Dropped) && e.count > 0;
            cornerColours = assignOne(listProperty(e, "color"), Role::Dropped) && e.count > 0;
        } else if (e.kind == Kind::Tristrips) {
            assignOne(listProperty(e, "vertex_indices"), Role::Strip);
        } else if (e.kind == Kind::RangeGrid && header.gridColumns > 0 && header.gridRows > 0) {
            // Without the grid's size its cells make no faces (and are named).
            assignOne(listProperty(e, "vertex_indices"), Role::GridCell);
        }
    }
    for (const Element& e : header.elements) {
        if (e.count == 0) continue;
        if (e.kind == Kind::Other) {
            if (e.name == "edge") edges = true;
            else if (e.name == "camera") camera = true;
            else out.otherElements.push_back(e.name);
            continue;
        }
        for (const Property& p : e.properties)
            if (p.role == Role::Other) out.otherProperties.push_back(e.name + "." + p.name);
    }
    // In the order and words loadMesh uses for every format.
    if (faceNormals) out.dropped.push_back("per-face normals");
    if (cornerColours) out.dropped.push_back("per-corner colours");
    if (radii) out.dropped.push_back("vertex radii");
    if (edges) out.dropped.push_back("edges");
    if (camera) out.dropped.push_back("camera parameters");
}

}  // namespace ply
}  // namespace vcgio
}  // namespace drm
