// Reads a .vtp file with VTK's own XML reader (vtkXMLPolyDataReader) and prints what VTK
// found, for tests/vtk_reader.rs to compare with the tool's .obj of the same mesh:
//   points N / polys M / normals K / v x y z (N lines, 17 digits) / f a b c (M lines).
// Exits 1 if VTK reports an error or the file holds no polygons.
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cstdio>

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: vtk_read_vtp FILE.vtp\n");
        return 2;
    }
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(argv[1]);
    reader->Update();
    vtkPolyData *data = reader->GetOutput();
    if (reader->GetErrorCode() != 0 || data == nullptr || data->GetNumberOfPolys() == 0) {
        std::fprintf(stderr, "VTK could not read %s\n", argv[1]);
        return 1;
    }
    vtkDataArray *normals = data->GetPointData()->GetNormals();
    std::printf("points %lld\npolys %lld\nnormals %lld\n", static_cast<long long>(data->GetNumberOfPoints()),
                static_cast<long long>(data->GetNumberOfPolys()),
                normals ? static_cast<long long>(normals->GetNumberOfTuples()) : 0LL);
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
        double p[3];
        data->GetPoint(i, p);
        std::printf("v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    }
    vtkNew<vtkIdList> ids;
    vtkCellArray *polys = data->GetPolys();
    polys->InitTraversal();
    while (polys->GetNextCell(ids)) {
        std::printf("f");
        for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) std::printf(" %lld", static_cast<long long>(ids->GetId(k)));
        std::printf("\n");
    }
    if (normals) {
        for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i) {
            double n[3];
            normals->GetTuple(i, n);
            std::printf("n %.17g %.17g %.17g\n", n[0], n[1], n[2]);
        }
    }
    return 0;
}
