// OpenCascade's side of the wire sweep benchmark (benches/wire.rs): reads one wire and
// profile, sweeps it with BRepOffsetAPI_MakePipeShell in corrected-Frenet and Frenet mode
// (made solid, the fastest of `repeats` builds, in a child process with a time limit), reads
// rmfsurf's STEP solid of the same wire, and measures all three with the same code
// (examples/occ/wire_sweep.hpp): validity, solids, volume, max |cos| between parameter lines,
// B-spline poles.
//
// Input (stdin, whitespace separated):
//   edges <n>, then per edge: line <p0> <p1> | arc <p0> <p1> <p2>
//                           | nurbs <degree> <poles> (x y z w)... <knots> k...
//   profile circle <r> | profile square <a>
//   frame <origin> <tangent> <f2>       (the profile's placement at the wire's start)
//   corner round | corner miter
//   repeats <n>
//   ours <path of rmfsurf's STEP file>
// Output (stdout): one line per sweep,
//   <name> built <0|1> valid <0|1> solids <n> volume <v> cos <c> poles <p> faces <b> <a> ms <t> failure <text>
#include "../../examples/occ/wire_sweep.hpp"

#include <iostream>
#include <stdexcept>

using namespace wire_sweep;

static void expect(std::istream &in, const std::string &word) {
    std::string got;
    if (!(in >> got) || got != word) throw std::runtime_error("expected '" + word + "', got '" + got + "'");
}

static gp_Pnt point(std::istream &in) {
    double x, y, z;
    in >> x >> y >> z;
    return gp_Pnt(x, y, z);
}

static void print(const char *name, const Measure &m) {
    std::printf("%s built %d valid %d solids %d volume %.17g cos %.17g poles %d faces %d %d ms %.6f failure %s\n", name,
                (int)m.built, (int)m.valid, m.solids, m.volume, m.max_cos, m.bspline_poles, m.bspline_faces,
                m.analytic_faces, m.seconds * 1e3, m.failure.empty() ? "-" : m.failure.c_str());
}

int main() {
    try {
        expect(std::cin, "edges");
        int n = 0;
        std::cin >> n;
        std::vector<Edge> wire(n);
        for (Edge &e : wire) {
            std::string kind;
            std::cin >> kind;
            if (kind == "line") {
                e.kind = Kind::Line, e.p[0] = point(std::cin), e.p[1] = point(std::cin);
            } else if (kind == "arc") {
                e.kind = Kind::Arc;
                for (gp_Pnt &p : e.p) p = point(std::cin);
            } else {
                e.kind = Kind::Nurbs;
                int poles = 0, knots = 0;
                std::cin >> e.degree >> poles;
                for (int i = 0; i < poles; ++i) {
                    e.poles.push_back(point(std::cin));
                    double w;
                    std::cin >> w;
                    e.weights.push_back(w);
                }
                std::cin >> knots;
                e.knots.resize(knots);
                for (double &k : e.knots) std::cin >> k;
            }
        }
        expect(std::cin, "profile");
        std::string kind;
        Profile profile;
        std::cin >> kind >> profile.size;
        profile.circle = kind == "circle";
        expect(std::cin, "frame");
        const gp_Pnt origin = point(std::cin);
        const gp_Pnt t = point(std::cin), f = point(std::cin);
        const gp_Dir tangent(t.X(), t.Y(), t.Z()), f2(f.X(), f.Y(), f.Z());
        expect(std::cin, "corner");
        std::cin >> kind;
        const bool round = kind == "round";
        expect(std::cin, "repeats");
        int repeats = 1;
        std::cin >> repeats;
        expect(std::cin, "ours");
        std::string path;
        std::cin >> path;
        if (!std::cin) throw std::runtime_error("bad input");
        print("rmfsurf", in_child([&] { return read_step(path); }, 1, 120));
        for (int frenet = 0; frenet <= 1; ++frenet)
            print(frenet ? "frenet" : "corrected_frenet",
                  in_child([&] { return pipe_shell(wire, profile, origin, tangent, f2, frenet == 1, round); }, repeats,
                           120));
        return 0;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "wire_pipe_shell: %s\n", e.what());
        return 1;
    }
}
