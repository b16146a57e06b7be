//! The B-rep model the wire and sheet operations get (RmfBrep): every accessor answers
//! within the counts, with indices in range, finite numbers, loops that run on from vertex
//! to vertex and shells holding each face once; one past the end is refused unwritten.

use rmfsurf_capi::brep::*;
use rmfsurf_capi::{RmfBrep, RmfVec3};

use super::session::{checked, is_poisoned, poisoned, status_ok};

/// Walks `brep` (from a successful call) through every accessor, then frees it.
pub(crate) fn walk(brep: *mut RmfBrep) {
    let ok = |name: &str, status| assert!(status_ok(name, status), "{name} refused in range");
    let mut counts = poisoned::<RmfBrepCounts>();
    ok("rmf_brep_counts", unsafe {
        rmf_brep_counts(brep, &mut counts)
    });
    assert!(counts.tolerance.is_finite() && counts.tolerance > 0.0);
    assert!(counts.face_count > 0 && counts.shell_count > 0);
    for i in 0..counts.vertex_count {
        let mut p = poisoned::<RmfVec3>();
        ok("rmf_brep_vertex", unsafe {
            rmf_brep_vertex(brep, i, &mut p)
        });
        assert!(p.x.is_finite() && p.y.is_finite() && p.z.is_finite());
    }
    let mut ends = Vec::with_capacity(counts.edge_count);
    let mut analytic_edges = Vec::with_capacity(counts.edge_count);
    for e in 0..counts.edge_count {
        let mut edge = poisoned::<RmfBrepEdge>();
        ok("rmf_brep_edge", unsafe {
            rmf_brep_edge(brep, e, &mut edge)
        });
        assert!(edge.start < counts.vertex_count && edge.end < counts.vertex_count);
        let c = edge.curve;
        assert!(
            c.pole_count > c.degree as usize
                && c.knot_count == c.pole_count + c.degree as usize + 1
        );
        // SAFETY: the view's arrays hold the counts it gives while the B-rep lives.
        let weights = unsafe { std::slice::from_raw_parts(c.weights, c.pole_count) };
        assert!(weights.iter().all(|w| w.is_finite() && *w > 0.0));
        ends.push((edge.start, edge.end));
        let mut analytic = poisoned::<RmfBrepAnalytic>();
        ok("rmf_brep_edge_analytic", unsafe {
            rmf_brep_edge_analytic(brep, e, &mut analytic)
        });
        if analytic.kind != RMF_ANALYTIC_NONE {
            assert!(matches!(
                analytic.kind,
                RMF_ANALYTIC_LINE | RMF_ANALYTIC_CIRCLE
            ));
            assert!(analytic.end.is_finite() && analytic.end > 0.0);
        }
        analytic_edges.push(analytic.kind != RMF_ANALYTIC_NONE);
    }
    let mut in_shell = vec![0usize; counts.face_count];
    for shell in 0..counts.shell_count {
        let mut view = poisoned::<RmfBrepShell>();
        ok("rmf_brep_shell", unsafe {
            rmf_brep_shell(brep, shell, &mut view)
        });
        // SAFETY: as above.
        let faces = unsafe { std::slice::from_raw_parts(view.faces, view.face_count) };
        faces.iter().for_each(|&f| in_shell[f] += 1);
    }
    assert!(in_shell.iter().all(|&n| n == 1), "every face in one shell");
    for f in 0..counts.face_count {
        let mut face = poisoned::<RmfBrepFace>();
        ok("rmf_brep_face", unsafe {
            rmf_brep_face(brep, f, &mut face)
        });
        let mut analytic = poisoned::<RmfBrepAnalytic>();
        ok("rmf_brep_face_analytic", unsafe {
            rmf_brep_face_analytic(brep, f, &mut analytic)
        });
        let curved = matches!(
            analytic.kind,
            RMF_ANALYTIC_CYLINDER | RMF_ANALYTIC_CONE | RMF_ANALYTIC_TORUS
        );
        for l in 0..face.loop_count {
            let mut bound = poisoned::<RmfBrepLoop>();
            ok("rmf_brep_loop", unsafe {
                rmf_brep_loop(brep, f, l, &mut bound)
            });
            let mut path = Vec::with_capacity(bound.use_count);
            let (mut in_model, mut on_analytic) = (Vec::new(), Vec::new());
            for k in 0..bound.use_count {
                let mut u = poisoned::<RmfBrepUse>();
                ok("rmf_brep_use", unsafe {
                    rmf_brep_use(brep, f, l, k, &mut u)
                });
                assert!(u.edge < counts.edge_count);
                let mut on = poisoned::<RmfBrepUse>();
                let status = unsafe { rmf_brep_analytic_use(brep, f, l, k, &mut on) };
                if analytic.kind == RMF_ANALYTIC_NONE {
                    assert!(!checked(
                        "rmf_brep_analytic_use",
                        status,
                        &[is_poisoned(&on)]
                    ));
                } else {
                    ok("rmf_brep_analytic_use", status);
                    on_analytic.push((on.edge, on.forward != 0));
                    if curved {
                        assert!(
                            analytic_edges[on.edge],
                            "an analytic face's edges are analytic"
                        );
                        assert_eq!(on.pcurve_kind, RMF_PCURVE_LINE);
                    }
                }
                in_model.push((u.edge, u.forward != 0));
                let (a, b) = ends[u.edge];
                path.push(if u.forward != 0 { (a, b) } else { (b, a) });
            }
            for k in 0..path.len() {
                assert_eq!(path[k].1, path[(k + 1) % path.len()].0, "a loop runs on");
            }
            // On the analytic surface the loop is the model's, or the model's run backwards
            // (where the surfaces' parameters have opposite orientations).
            if !on_analytic.is_empty() {
                let backwards: Vec<_> = in_model.iter().rev().map(|&(e, f)| (e, !f)).collect();
                assert!(
                    on_analytic == in_model || on_analytic == backwards,
                    "the analytic loop is the model's"
                );
            }
        }
    }
    let mut edge = poisoned::<RmfBrepEdge>();
    let status = unsafe { rmf_brep_edge(brep, counts.edge_count, &mut edge) };
    assert!(!checked("rmf_brep_edge", status, &[is_poisoned(&edge)]));
    unsafe { rmf_brep_free(brep) };
}
