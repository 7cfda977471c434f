//! Pictures for people who would rather look than read: an isometric drawing of the
//! machine's axes, each tilted plane as a patch with its X', Y', Z', the tool coming from
//! the side Z' points to, probed points with their deviations exaggerated and labelled,
//! and text lines (rotary positions, warnings).
//!
//! The projection, stated so that a reader (and `cli/tests/cli.rs`) can check every drawn
//! coordinate against the numbers: a point `(x, y, z)` in millimetres is drawn at
//!
//! ```text
//! u = (x + y)·cos 30°            (to the right)
//! w = z + (y − x)·sin 30°        (up)
//! svg x = data-u0 + data-scale·u,  svg y = data-v0 − data-scale·w
//! ```
//!
//! with `data-scale`, `data-u0`, `data-v0` written on the root element. The machine's X
//! runs to the lower right, Y to the upper right and Z up: the view from the front right,
//! above the table, along `(−1, 1, −1)`. A plane whose Z' has a component toward the viewer
//! shows its upper face (blue); otherwise its underside (orange). A Z' with a negative Z
//! component is a plane upside down for a tool that comes from above: it is said in red.

use cncrot::{Frame, Vector};
use std::fmt::Write;

/// One tilted plane to draw.
pub struct Plane {
    pub frame: Frame,
    /// Written beside the plane (`line 4`); empty for none.
    pub label: String,
}

/// What a picture shows.
pub struct Picture {
    pub title: String,
    pub planes: Vec<Plane>,
    /// Half the side of each plane patch, mm.
    pub size: f64,
    /// Probed points and their signed distances from the (first) plane along its Z'.
    pub points: Vec<(Vector, f64)>,
    /// Text lines under the title (rotary positions, remarks).
    pub notes: Vec<String>,
}

const WIDTH: f64 = 720.0;
const HEIGHT: f64 = 540.0;
const MARGIN: f64 = 60.0;
/// The room the title and notes take at the top.
const TEXT_ROOM: f64 = 24.0;
/// Where the viewer stands (unnormalised): the upper face of a plane faces it when Z'
/// has a positive component along it.
const VIEWER: Vector = [1.0, -1.0, 1.0];

/// The projection of the module doc, before scaling: (right, up).
pub fn project(p: Vector) -> (f64, f64) {
    let (s, c) = (0.5, 3f64.sqrt() / 2.0);
    ((p[0] + p[1]) * c, p[2] + (p[1] - p[0]) * s)
}

fn add(a: Vector, b: Vector, k: f64) -> Vector {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}

fn dot(a: Vector, b: Vector) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn column(f: &Frame, k: usize) -> Vector {
    let r = &f.rotation;
    [r[0][k], r[1][k], r[2][k]]
}

/// Text safe inside an SVG element or attribute.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Maps model points to the picture: scale and offsets.
struct View {
    scale: f64,
    u0: f64,
    v0: f64,
}

impl View {
    fn fit(points: &[Vector], notes: usize) -> View {
        let (mut lo_u, mut hi_u, mut lo_w, mut hi_w) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for &p in points {
            let (u, w) = project(p);
            lo_u = lo_u.min(u);
            hi_u = hi_u.max(u);
            lo_w = lo_w.min(w);
            hi_w = hi_w.max(w);
        }
        let top = MARGIN + TEXT_ROOM * (notes as f64 + 1.0);
        let room_u = WIDTH - 2.0 * MARGIN;
        let room_w = (HEIGHT - top - MARGIN).max(100.0);
        let span_u = (hi_u - lo_u).max(1e-9);
        let span_w = (hi_w - lo_w).max(1e-9);
        let scale = (room_u / span_u).min(room_w / span_w);
        // Centred in the room left by the text.
        let u0 = MARGIN + (room_u - scale * span_u) / 2.0 - scale * lo_u;
        let v0 = top + (room_w - scale * span_w) / 2.0 + scale * hi_w;
        View { scale, u0, v0 }
    }

    fn at(&self, p: Vector) -> (f64, f64) {
        let (u, w) = project(p);
        (self.u0 + self.scale * u, self.v0 - self.scale * w)
    }
}

/// A number as the picture writes it: enough digits to check coordinates to 1e-6 px.
fn n(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

fn arrow(
    out: &mut String,
    view: &View,
    id: &str,
    from: Vector,
    to: Vector,
    colour: &str,
    label: &str,
) {
    let (x1, y1) = view.at(from);
    let (x2, y2) = view.at(to);
    let _ = writeln!(
        out,
        r#"  <line id="{id}" x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="2" marker-end="url(#head)" data-from="{} {} {}" data-to="{} {} {}"/>"#,
        n(x1),
        n(y1),
        n(x2),
        n(y2),
        n(from[0]),
        n(from[1]),
        n(from[2]),
        n(to[0]),
        n(to[1]),
        n(to[2]),
    );
    if !label.is_empty() {
        // The label a little beyond the tip, along the arrow.
        let (dx, dy) = (x2 - x1, y2 - y1);
        let len = (dx * dx + dy * dy).sqrt().max(1e-9);
        let _ = writeln!(
            out,
            r#"  <text x="{}" y="{}" fill="{colour}" font-size="15" text-anchor="middle" dominant-baseline="middle">{}</text>"#,
            n(x2 + 14.0 * dx / len),
            n(y2 + 14.0 * dy / len),
            escape(label)
        );
    }
}

/// The picture as SVG text.
pub fn render(p: &Picture) -> String {
    let size = if p.size.is_finite() && p.size > 0.0 {
        p.size
    } else {
        50.0
    };
    // Every point the drawing uses, to fit it into the page.
    let mut model: Vec<Vector> = Vec::new();
    let machine_len = size * 1.2;
    let origin = [0.0; 3];
    model.extend([
        origin,
        [machine_len, 0.0, 0.0],
        [0.0, machine_len, 0.0],
        [0.0, 0.0, machine_len],
    ]);
    for pl in &p.planes {
        let (x, y, z) = (
            column(&pl.frame, 0),
            column(&pl.frame, 1),
            column(&pl.frame, 2),
        );
        let o = pl.frame.translation;
        for (a, b) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
            model.push(add(add(o, x, a * size), y, b * size));
        }
        model.push(add(o, z, 1.6 * size));
    }
    // Deviations are drawn enlarged so that the largest spans a quarter of the patch.
    let worst = p.points.iter().fold(0.0f64, |m, (_, d)| m.max(d.abs()));
    let gain = if worst > 0.0 {
        (0.25 * size / worst).max(1.0)
    } else {
        1.0
    };
    let normal = p.planes.first().map(|pl| column(&pl.frame, 2));
    let drawn: Vec<(Vector, Vector)> = p
        .points
        .iter()
        .map(|&(q, d)| match normal {
            Some(z) => {
                let foot = add(q, z, -d);
                (foot, add(foot, z, d * gain))
            }
            None => (q, q),
        })
        .collect();
    model.extend(drawn.iter().flat_map(|&(f, q)| [f, q]));
    let mut notes = p.notes.clone();
    for pl in &p.planes {
        let z = column(&pl.frame, 2);
        if z[2] < 0.0 {
            let which = if pl.label.is_empty() {
                String::new()
            } else {
                format!(" ({})", pl.label)
            };
            notes.push(format!(
                "Z' points down{which}: the plane is upside down, the tool would come from below"
            ));
        }
    }
    if gain > 1.0 {
        notes.push(format!("deviations drawn {gain:.0} times enlarged"));
    }
    let view = View::fit(&model, notes.len());

    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" data-projection="isometric" data-scale="{}" data-u0="{}" data-v0="{}">
  <title>{}</title>
  <defs><marker id="head" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M0 0 L10 5 L0 10 z" fill="context-stroke"/></marker></defs>
  <rect width="100%" height="100%" fill="white"/>"#,
        // Exact, so that a reader recomputes the coordinates to their written 1e-6.
        view.scale,
        view.u0,
        view.v0,
        escape(&p.title),
        w = WIDTH,
        h = HEIGHT,
    );
    let _ = writeln!(
        out,
        r#"  <text x="{}" y="{}" font-size="17" font-weight="bold">{}</text>"#,
        MARGIN / 2.0,
        MARGIN / 2.0 + 4.0,
        escape(&p.title)
    );
    for (k, note) in notes.iter().enumerate() {
        let warn = note.starts_with("Z' points down");
        let _ = writeln!(
            out,
            r#"  <text class="{}" x="{}" y="{}" font-size="14" fill="{}">{}</text>"#,
            if warn { "warning" } else { "note" },
            MARGIN / 2.0,
            MARGIN / 2.0 + 4.0 + TEXT_ROOM * (k as f64 + 1.0),
            if warn { "#c00000" } else { "#333333" },
            escape(note)
        );
    }
    for (k, name) in ["X", "Y", "Z"].iter().enumerate() {
        let mut to = [0.0; 3];
        to[k] = machine_len;
        arrow(
            &mut out,
            &view,
            &format!("machine-{name}"),
            origin,
            to,
            "#777777",
            name,
        );
    }
    for (k, pl) in p.planes.iter().enumerate() {
        let (x, y, z) = (
            column(&pl.frame, 0),
            column(&pl.frame, 1),
            column(&pl.frame, 2),
        );
        let o = pl.frame.translation;
        let corners: Vec<(f64, f64)> = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
            .iter()
            .map(|&(a, b)| view.at(add(add(o, x, a * size), y, b * size)))
            .collect();
        let upper = dot(z, VIEWER) >= 0.0;
        let pts: Vec<String> = corners
            .iter()
            .map(|(u, v)| format!("{},{}", n(*u), n(*v)))
            .collect();
        let suffix = if k == 0 {
            String::new()
        } else {
            format!("-{k}")
        };
        let _ = writeln!(
            out,
            r##"  <polygon id="plane{suffix}" class="{}" points="{}" fill="{}" fill-opacity="0.55" stroke="#3a6ea5" stroke-width="1.5" data-origin="{} {} {}" data-size="{}"/>"##,
            if upper { "upper-face" } else { "underside" },
            pts.join(" "),
            if upper { "#9ecae1" } else { "#fdae6b" },
            o[0],
            o[1],
            o[2],
            size,
        );
        if !pl.label.is_empty() {
            let (u, v) = view.at(add(add(o, x, size), y, -size));
            let _ = writeln!(
                out,
                r##"  <text x="{}" y="{}" font-size="13" fill="#3a6ea5">{}</text>"##,
                n(u + 6.0),
                n(v + 14.0),
                escape(&pl.label)
            );
        }
        // The tool: a shank above the plane on the side Z' points to.
        let (t1, t2) = (add(o, z, 0.9 * size), add(o, z, 1.6 * size));
        let (a1, b1) = view.at(t1);
        let (a2, b2) = view.at(t2);
        let _ = writeln!(
            out,
            r##"  <line id="tool{suffix}" x1="{}" y1="{}" x2="{}" y2="{}" stroke="#555555" stroke-width="9" stroke-linecap="round" opacity="0.6"/>"##,
            n(a1),
            n(b1),
            n(a2),
            n(b2),
        );
        for (name, dir, colour) in [
            ("X'", x, "#d62728"),
            ("Y'", y, "#2ca02c"),
            ("Z'", z, "#1f4ed8"),
        ] {
            let id = format!(
                "{}-prime{suffix}",
                name.trim_end_matches('\'').to_lowercase()
            );
            arrow(
                &mut out,
                &view,
                &id,
                o,
                add(o, dir, 0.8 * size),
                colour,
                name,
            );
        }
    }
    for (k, (&(q, d), &(foot, shown))) in p.points.iter().zip(&drawn).enumerate() {
        let (fx, fy) = view.at(foot);
        let (px, py) = view.at(shown);
        let _ = writeln!(
            out,
            r##"  <line class="deviation" x1="{}" y1="{}" x2="{}" y2="{}" stroke="#9467bd" stroke-width="1.5"/>"##,
            n(fx),
            n(fy),
            n(px),
            n(py)
        );
        let _ = writeln!(
            out,
            r##"  <circle class="point" id="P{}" cx="{}" cy="{}" r="4" fill="#9467bd" data-xyz="{} {} {}" data-deviation="{}"/>"##,
            k + 1,
            n(px),
            n(py),
            q[0],
            q[1],
            q[2],
            d,
        );
        let _ = writeln!(
            out,
            r##"  <text x="{}" y="{}" font-size="12" fill="#5b3c88">P{} {:+.4}</text>"##,
            n(px + 7.0),
            n(py - 7.0),
            k + 1,
            d
        );
    }
    out.push_str("</svg>\n");
    out
}

/// Writes the picture to `path`.
pub fn write(path: &str, p: &Picture) -> Result<(), crate::input::Failure> {
    std::fs::write(path, render(p))
        .map_err(|e| crate::input::Failure::new(format!("--svg {path}: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The axes of the isometric drawing: unit length, X, −Y and Z 120° apart (X and Y 60°),
    /// Z straight up.
    #[test]
    fn isometric_axes() {
        let (xu, xw) = project([1.0, 0.0, 0.0]);
        let (yu, yw) = project([0.0, 1.0, 0.0]);
        let (zu, zw) = project([0.0, 0.0, 1.0]);
        for (u, w) in [(xu, xw), (yu, yw), (zu, zw)] {
            assert!(((u * u + w * w).sqrt() - 1.0).abs() < 1e-15);
        }
        assert!(xu > 0.0 && xw < 0.0 && yu > 0.0 && yw > 0.0);
        assert_eq!((zu, zw), (0.0, 1.0));
        // The viewer's direction projects to a point.
        let (vu, vw) = project(VIEWER);
        assert!(vu.abs() < 1e-15 && vw.abs() < 1e-15);
        assert!((xu * yu + xw * yw - 0.5).abs() < 1e-15);
    }
}
