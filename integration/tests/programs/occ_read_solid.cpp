// Reads a STEP file with OpenCascade's STEP reader (STEPControl_Reader, as FreeCAD, CadQuery
// and build123d do), or a file in OpenCascade's own B-rep text (name ending in .brep) with
// BRepTools::Read, and checks that it holds one valid closed solid: BRepCheck_Analyzer,
// no free edges (ShapeAnalysis_FreeBounds), every shell closed; prints its face count,
// volume (BRepGProp) and, given an expected volume as the second argument, the relative
// difference, which must be below the third argument. Exit status 0 on success.
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shape.hxx>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char **argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: occ_read_solid FILE.step|FILE.brep [expected_volume tolerance]\n");
        return 2;
    }
    const size_t name_length = std::strlen(argv[1]);
    TopoDS_Shape shape;
    if (name_length > 5 && std::strcmp(argv[1] + name_length - 5, ".brep") == 0) {
        BRep_Builder builder;
        if (!BRepTools::Read(shape, argv[1], builder)) {
            std::fprintf(stderr, "%s: not read\n", argv[1]);
            return 1;
        }
    } else {
        STEPControl_Reader reader;
        if (reader.ReadFile(argv[1]) != IFSelect_RetDone) {
            std::fprintf(stderr, "%s: not read\n", argv[1]);
            return 1;
        }
        reader.TransferRoots();
        shape = reader.OneShape();
    }
    int solids = 0, shells = 0, faces = 0, open_shells = 0;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++solids;
    for (TopExp_Explorer e(shape, TopAbs_SHELL); e.More(); e.Next()) {
        ++shells;
        if (!BRep_Tool::IsClosed(e.Current())) ++open_shells;
    }
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++faces;
    const bool valid = BRepCheck_Analyzer(shape).IsValid();
    ShapeAnalysis_FreeBounds bounds(shape);
    int free_wires = 0;
    for (TopExp_Explorer e(bounds.GetClosedWires(), TopAbs_WIRE); e.More(); e.Next()) ++free_wires;
    for (TopExp_Explorer e(bounds.GetOpenWires(), TopAbs_WIRE); e.More(); e.Next()) ++free_wires;
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props, 1e-9);
    const double volume = props.Mass();
    std::printf("OpenCascade reads %s: %d solid(s), %d shell(s) (%d open), %d faces, BRepCheck valid %s, "
                "%d free boundary wires, volume %.9f\n",
                argv[1], solids, shells, open_shells, faces, valid ? "yes" : "NO", free_wires, volume);
    bool ok = solids == 1 && shells == 1 && open_shells == 0 && valid && free_wires == 0;
    if (argc >= 4) {
        const double expected = std::atof(argv[2]), limit = std::atof(argv[3]);
        const double error = std::fabs(volume - expected) / expected;
        std::printf("  volume against the expected %.9f: relative %.3e (limit %.1e)\n", expected, error, limit);
        ok = ok && error <= limit;
    }
    return ok ? 0 : 1;
}
