//! Consecutive mutable pieces of one slice, for parallel passes that each fill their own part
//! of a shared array (the stars' ranges, the Morton sort's buckets, the marching-cubes bricks'
//! resolved triangles).

/// `items` cut into consecutive mutable pieces, piece `i` from `firsts[i] - firsts[0]` to where
/// the next starts (`firsts` ascending, every difference within `items`).
pub(crate) fn split_at<'a, T>(items: &'a mut [T], firsts: &[usize]) -> Vec<&'a mut [T]> {
    let mut pieces = Vec::with_capacity(firsts.len());
    let mut rest = items;
    let mut at = firsts.first().copied().unwrap_or(0);
    for next in firsts.iter().skip(1).copied().chain([at + rest.len()]) {
        let (piece, tail) = rest.split_at_mut(next - at);
        pieces.push(piece);
        rest = tail;
        at = next;
    }
    pieces
}
