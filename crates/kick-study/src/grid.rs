//! The one grid-index decoder of the experiment files (1D and 3D): cell
//! `index` of a grid of axes is, for each axis, a position in its values, in
//! C order (the last axis varies fastest).

/// Call `visit(axis, position)` for every axis of a grid of axes of these
/// `lengths` at cell `index`, last axis first. No allocation: it runs once
/// per row of a sweep.
pub fn decode(lengths: impl DoubleEndedIterator<Item = usize> + ExactSizeIterator, index: u64, mut visit: impl FnMut(usize, usize)) {
    let mut rest = index;
    for (axis, n) in lengths.enumerate().rev() {
        let n = n as u64;
        visit(axis, (rest % n) as usize);
        rest /= n;
    }
}

#[cfg(test)]
mod tests {
    use super::decode;

    /// Every cell of a 2 x 3 x 4 grid once, in C order.
    #[test]
    fn cells_come_in_c_order() {
        let lengths = [2usize, 3, 4];
        let mut k = 0;
        for i in 0..2 {
            for j in 0..3 {
                for l in 0..4 {
                    let mut at = [usize::MAX; 3];
                    decode(lengths.iter().copied(), k, |axis, position| at[axis] = position);
                    assert_eq!(at, [i, j, l], "cell {k}");
                    k += 1;
                }
            }
        }
    }
}
