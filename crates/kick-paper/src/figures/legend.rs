//! Where a panel's legend goes: the first corner or edge, in order of
//! preference, whose box covers no drawn curve or marker; failing that, the
//! y range grows at the top until one is free. The box is measured as
//! plotters draws it (`SeriesLabelStyle::draw`: the labels' text box, a 30 px
//! key column and 10 px margins), so what is tested is what is drawn.

use plotters::element::MultiLineText;
use plotters::prelude::*;

/// plotters' legend key column and margin (its defaults, used in every figure).
const KEY: i32 = 30;
const MARGIN: i32 = 10;
/// Gap plotters leaves between the legend and the plot's edge.
const EDGE: i32 = 5;
/// Clearance kept between the box and a curve: half the line width plus the marker radius.
const CLEARANCE: i32 = 4;
/// Top headroom tried, as a fraction of the data's y span.
/// A small panel with a long legend may need the data squeezed to a third
/// of the height; covered data is worse.
pub const HEADROOM: [f64; 8] = [0.0, 0.15, 0.3, 0.5, 0.8, 1.2, 1.7, 2.4];

/// Positions tried after the panel's own choice.
const ORDER: [SeriesLabelPosition; 8] = [
    SeriesLabelPosition::UpperRight,
    SeriesLabelPosition::UpperLeft,
    SeriesLabelPosition::LowerRight,
    SeriesLabelPosition::LowerLeft,
    SeriesLabelPosition::UpperMiddle,
    SeriesLabelPosition::LowerMiddle,
    SeriesLabelPosition::MiddleRight,
    SeriesLabelPosition::MiddleLeft,
];

/// Size in pixels of the legend box of these labels in `font`.
pub fn box_size(labels: &[&str], font: &TextStyle) -> Result<(i32, i32), String> {
    let mut text = MultiLineText::<_, &str>::new((0, 0), font);
    for label in labels {
        text.push_line(*label);
    }
    let (w, h) = text.estimate_dimension().map_err(|e| format!("{e:?}"))?;
    Ok((w + KEY + 2 * MARGIN, h + 2 * MARGIN))
}

/// Top-left corner of a box of `size` at `position` in a plot of `plot` pixels
/// (plotters' `layout_label_area`).
fn corner(position: &SeriesLabelPosition, size: (i32, i32), plot: (i32, i32)) -> (i32, i32) {
    use SeriesLabelPosition::*;
    let x = match position {
        UpperLeft | MiddleLeft | LowerLeft => EDGE,
        UpperMiddle | MiddleMiddle | LowerMiddle => (plot.0 - size.0) / 2,
        UpperRight | MiddleRight | LowerRight => plot.0 - size.0 - EDGE,
        Coordinate(x, _) => *x,
    };
    let y = match position {
        UpperLeft | UpperMiddle | UpperRight => EDGE,
        MiddleLeft | MiddleMiddle | MiddleRight => (plot.1 - size.1) / 2,
        LowerLeft | LowerMiddle | LowerRight => plot.1 - size.1 - EDGE,
        Coordinate(_, y) => *y,
    };
    (x, y)
}

/// Points along the polylines `curves` (pixels, relative to the plot) inside
/// the box at `corner` of `size`, widened by the clearance: every segment is
/// walked in steps of at most 2 px.
pub fn covered(curves: &[Vec<(i32, i32)>], corner: (i32, i32), size: (i32, i32)) -> usize {
    let (x0, y0) = (corner.0 - CLEARANCE, corner.1 - CLEARANCE);
    let (x1, y1) = (corner.0 + size.0 + CLEARANCE, corner.1 + size.1 + CLEARANCE);
    let inside = |x: f64, y: f64| x >= x0 as f64 && x <= x1 as f64 && y >= y0 as f64 && y <= y1 as f64;
    let mut count = 0;
    for curve in curves {
        if let [only] = curve.as_slice() {
            count += usize::from(inside(only.0 as f64, only.1 as f64));
        }
        for pair in curve.windows(2) {
            let (a, b) = ((pair[0].0 as f64, pair[0].1 as f64), (pair[1].0 as f64, pair[1].1 as f64));
            let steps = ((b.0 - a.0).abs().max((b.1 - a.1).abs()) / 2.0).ceil().clamp(1.0, 1e5) as usize;
            for k in 0..=steps {
                let t = k as f64 / steps as f64;
                count += usize::from(inside(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
        }
    }
    count
}

/// The first free position for a box of `size` in a plot of `plot` pixels
/// (`preferred` first), as the box's corner; `None` when every one covers data.
pub fn free_position(
    curves: &[Vec<(i32, i32)>],
    size: (i32, i32),
    plot: (i32, i32),
    preferred: &SeriesLabelPosition,
) -> Option<(i32, i32)> {
    std::iter::once(preferred)
        .chain(ORDER.iter())
        .map(|p| corner(p, size, plot))
        .find(|&c| c.0 >= 0 && c.1 >= 0 && covered(curves, c, size) == 0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(from: (i32, i32), to: (i32, i32)) -> Vec<(i32, i32)> {
        vec![from, to]
    }

    #[test]
    fn a_diagonal_through_the_upper_right_sends_the_legend_to_the_upper_left() {
        let plot = (600, 400);
        // From the lower left to the upper right corner: UpperRight is covered,
        // UpperLeft is free.
        let curves = vec![line((0, 399), (599, 0))];
        let size = (150, 60);
        assert!(covered(&curves, corner(&SeriesLabelPosition::UpperRight, size, plot), size) > 0);
        assert_eq!(free_position(&curves, size, plot, &SeriesLabelPosition::UpperRight), Some((EDGE, EDGE)));
    }

    #[test]
    fn a_curve_everywhere_leaves_no_free_position() {
        let plot = (600, 400);
        // A zigzag every 20 px fills the plot.
        let zigzag: Vec<(i32, i32)> = (0..=30).map(|k| (k * 20, if k % 2 == 0 { 0 } else { 399 })).collect();
        assert_eq!(free_position(&[zigzag], (150, 60), plot, &SeriesLabelPosition::UpperRight), None);
    }

    #[test]
    fn the_clearance_counts_a_curve_just_outside_the_box() {
        let size = (100, 50);
        let corner = (200, 100);
        // 3 px right of the box: inside the clearance; 6 px: outside.
        assert!(covered(&[line((303, 0), (303, 400))], corner, size) > 0);
        assert_eq!(covered(&[line((306, 0), (306, 400))], corner, size), 0);
    }
}
