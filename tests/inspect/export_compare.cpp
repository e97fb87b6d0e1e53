// Compares two ParaView exports array for array: usage export_compare A B, where A and B
// are export folders (surface.pvd with .vts or .pvts datasets; a .pvts is read through
// VTK's parallel reader, which joins its pieces). Every dataset of the collections, in
// order, must have the same time, extent, points and point arrays (names, components,
// values, bit for bit) and the same field data. Exits 0 when they are equal, 1 with the
// first difference otherwise.
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLPStructuredGridReader.h>
#include <vtkXMLStructuredGridReader.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Entry {
    std::string time, part, file;
};

std::vector<Entry> collection(const fs::path& dir) {
    std::ifstream in(dir / "surface.pvd");
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    const std::regex data_set(R"re(<DataSet timestep="([^"]*)" part="([^"]*)" file="([^"]*)"/>)re");
    std::vector<Entry> out;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), data_set); it != std::sregex_iterator(); ++it)
        out.push_back({(*it)[1], (*it)[2], (*it)[3]});
    return out;
}

vtkStructuredGrid* read(const fs::path& file, vtkNew<vtkXMLStructuredGridReader>& serial,
                        vtkNew<vtkXMLPStructuredGridReader>& parallel) {
    if (file.extension() == ".pvts") {
        parallel->SetFileName(file.c_str());
        parallel->Update();
        return parallel->GetOutput();
    }
    serial->SetFileName(file.c_str());
    serial->Update();
    return serial->GetOutput();
}

bool same_array(vtkDataArray* a, vtkDataArray* b, std::string& why) {
    if (a->GetNumberOfTuples() != b->GetNumberOfTuples() || a->GetNumberOfComponents() != b->GetNumberOfComponents()) {
        why = "sizes differ";
        return false;
    }
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
        for (int c = 0; c < a->GetNumberOfComponents(); ++c)
            if (a->GetComponent(t, c) != b->GetComponent(t, c)) {
                std::ostringstream o;
                o.precision(17);
                o << "tuple " << t << " component " << c << ": " << a->GetComponent(t, c)
                  << " != " << b->GetComponent(t, c);
                why = o.str();
                return false;
            }
    return true;
}

bool same_field_data(vtkFieldData* a, vtkFieldData* b, std::string& why) {
    if (a->GetNumberOfArrays() != b->GetNumberOfArrays()) {
        why = "field data: numbers of arrays differ";
        return false;
    }
    for (int k = 0; k < a->GetNumberOfArrays(); ++k) {
        vtkAbstractArray* x = a->GetAbstractArray(k);
        vtkAbstractArray* y = b->GetAbstractArray(x->GetName());
        if (y == nullptr) {
            why = std::string("field data: no ") + x->GetName();
            return false;
        }
        if (auto* xs = vtkStringArray::SafeDownCast(x)) {
            auto* ys = vtkStringArray::SafeDownCast(y);
            bool same = ys != nullptr && xs->GetNumberOfValues() == ys->GetNumberOfValues();
            for (vtkIdType v = 0; same && v < xs->GetNumberOfValues(); ++v) same = xs->GetValue(v) == ys->GetValue(v);
            if (!same) {
                why = std::string("field data ") + x->GetName() + " differs";
                return false;
            }
        } else if (!same_array(vtkDataArray::SafeDownCast(x), vtkDataArray::SafeDownCast(y), why)) {
            why = std::string("field data ") + x->GetName() + ": " + why;
            return false;
        }
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s EXPORT_A EXPORT_B\n", argv[0]);
        return 2;
    }
    const fs::path a_dir = argv[1], b_dir = argv[2];
    const std::vector<Entry> a = collection(a_dir), b = collection(b_dir);
    if (a.empty() || a.size() != b.size()) {
        std::printf("the collections differ: %zu and %zu datasets\n", a.size(), b.size());
        return 1;
    }
    std::size_t arrays = 0, values = 0;
    for (std::size_t d = 0; d < a.size(); ++d) {
        if (a[d].time != b[d].time || a[d].part != b[d].part) {
            std::printf("dataset %zu: time or part differs (%s/%s, %s/%s)\n", d, a[d].time.c_str(), a[d].part.c_str(),
                        b[d].time.c_str(), b[d].part.c_str());
            return 1;
        }
        vtkNew<vtkXMLStructuredGridReader> sa, sb;
        vtkNew<vtkXMLPStructuredGridReader> pa, pb;
        vtkStructuredGrid* x = read(a_dir / a[d].file, sa, pa);
        vtkStructuredGrid* y = read(b_dir / b[d].file, sb, pb);
        int ex[6], ey[6];
        x->GetExtent(ex);
        y->GetExtent(ey);
        std::string why;
        bool same = std::equal(ex, ex + 6, ey);
        if (!same) why = "extents differ";
        if (same && !same_array(x->GetPoints()->GetData(), y->GetPoints()->GetData(), why)) {
            why = "points: " + why;
            same = false;
        }
        vtkPointData *px = x->GetPointData(), *py = y->GetPointData();
        if (same && px->GetNumberOfArrays() != py->GetNumberOfArrays()) {
            why = "numbers of point arrays differ";
            same = false;
        }
        for (int k = 0; same && k < px->GetNumberOfArrays(); ++k) {
            vtkDataArray* ax = px->GetArray(k);
            vtkDataArray* ay = py->GetArray(ax->GetName());
            if (ay == nullptr) {
                why = std::string("no array ") + ax->GetName();
                same = false;
            } else if (!same_array(ax, ay, why)) {
                why = std::string(ax->GetName()) + ": " + why;
                same = false;
            }
            values += static_cast<std::size_t>(ax->GetNumberOfValues());
            ++arrays;
        }
        if (same && !same_field_data(x->GetFieldData(), y->GetFieldData(), why)) same = false;
        if (!same) {
            std::printf("%s and %s differ: %s\n", (a_dir / a[d].file).c_str(), (b_dir / b[d].file).c_str(),
                        why.c_str());
            return 1;
        }
    }
    std::printf("equal: %zu datasets, %zu point arrays, %zu values, every one bit for bit\n", a.size(), arrays, values);
    return 0;
}
