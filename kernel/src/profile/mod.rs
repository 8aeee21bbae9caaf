//! Planar profiles for sweeps: circle, rectangle and polygon with holes (even-odd rule), each with
//! an exact signed distance in its plane, area and centroid (for Pappus volumes), outlines and
//! cap triangulations (for tessellations).

mod block;
mod circle;
mod edges;
mod error;
mod nearest;
mod polygon;
mod rectangle;
mod triangulate;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_block;

pub use circle::Circle;
pub use error::ProfileError;
pub use polygon::Polygon;
pub(crate) use polygon::loops_distance;
pub use rectangle::Rectangle;
pub use triangulate::triangulate;

use glam::DVec2;

/// A planar region, negative inside.
#[derive(Debug, Clone, PartialEq)]
pub enum Profile {
    /// A disc.
    Circle(Circle),
    /// An axis-aligned rectangle.
    Rectangle(Rectangle),
    /// A polygon with holes.
    Polygon(Polygon),
}

impl Profile {
    /// The disc of radius `radius` around the origin.
    pub fn circle(radius: f64) -> Result<Profile, ProfileError> {
        Profile::Circle(Circle {
            center: DVec2::ZERO,
            radius,
        })
        .checked()
    }

    /// The rectangle of size `size` centred at the origin.
    pub fn rectangle(size: DVec2) -> Result<Profile, ProfileError> {
        Profile::Rectangle(Rectangle {
            center: DVec2::ZERO,
            size,
        })
        .checked()
    }

    /// The polygon with outline `points` and `holes`.
    pub fn polygon(points: Vec<DVec2>, holes: Vec<Vec<DVec2>>) -> Result<Profile, ProfileError> {
        Ok(Profile::Polygon(Polygon::new(points, holes)?))
    }

    /// The profile if its parameters are valid.
    pub fn checked(self) -> Result<Profile, ProfileError> {
        self.validate()?;
        Ok(self)
    }

    /// The profile's name in the JSON tree format.
    pub fn name(&self) -> &'static str {
        match self {
            Profile::Circle(_) => "circle",
            Profile::Rectangle(_) => "rectangle",
            Profile::Polygon(_) => "polygon",
        }
    }

    /// Checks the parameters (polygons are checked when built).
    pub fn validate(&self) -> Result<(), ProfileError> {
        match self {
            Profile::Circle(c) => c.validate(),
            Profile::Rectangle(r) => r.validate(),
            Profile::Polygon(_) => Ok(()),
        }
    }

    /// Exact signed distance at `q` (negative inside).
    pub fn distance(&self, q: DVec2) -> f64 {
        self.distance_gradient(q).0
    }

    /// Exact signed distance and its gradient (unit length).
    pub fn distance_gradient(&self, q: DVec2) -> (f64, DVec2) {
        match self {
            Profile::Circle(c) => c.distance_gradient(q),
            Profile::Rectangle(r) => r.distance_gradient(q),
            Profile::Polygon(p) => p.distance_gradient(q),
        }
    }

    /// [`Profile::distance_gradient`] at every point of `qs`, appended to `out` (the same
    /// answers; a polygon with many edges measures a block of nearby points faster together).
    pub fn distance_gradients(&self, qs: &[DVec2], out: &mut Vec<(f64, DVec2)>) {
        match self {
            Profile::Polygon(p) if p.index.is_some() => {
                let mut near = Vec::with_capacity(qs.len());
                p.nearest_many(qs, &mut near);
                out.extend(near.iter().map(|n| (n.distance, n.gradient)));
            }
            _ => out.extend(qs.iter().map(|&q| self.distance_gradient(q))),
        }
    }

    /// The bounding rectangle `(min, max)`.
    pub fn bounds(&self) -> (DVec2, DVec2) {
        match self {
            Profile::Circle(c) => (
                c.center - DVec2::splat(c.radius),
                c.center + DVec2::splat(c.radius),
            ),
            Profile::Rectangle(r) => (r.center - r.size * 0.5, r.center + r.size * 0.5),
            Profile::Polygon(p) => p
                .loops()
                .iter()
                .flatten()
                .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), c| {
                    (lo.min(*c), hi.max(*c))
                }),
        }
    }

    /// The largest distance from the origin to a point of the region.
    pub fn radius(&self) -> f64 {
        match self {
            Profile::Circle(c) => c.center.length() + c.radius,
            Profile::Rectangle(r) => r.corners().iter().map(|c| c.length()).fold(0.0, f64::max),
            Profile::Polygon(p) => p
                .loops()
                .iter()
                .flatten()
                .map(|c| c.length())
                .fold(0.0, f64::max),
        }
    }

    /// Area and centroid of the region.
    pub fn area_centroid(&self) -> (f64, DVec2) {
        match self {
            Profile::Circle(c) => (std::f64::consts::PI * c.radius * c.radius, c.center),
            Profile::Rectangle(r) => (r.size.x * r.size.y, r.center),
            Profile::Polygon(p) => p.area_centroid(),
        }
    }

    /// The boundary as closed loops of points (a circle as `segments` points; rectangles and
    /// polygons as their corners), for tessellation.
    pub fn outline(&self, segments: usize) -> Vec<Vec<DVec2>> {
        match self {
            Profile::Circle(c) => vec![c.outline(segments.max(3))],
            Profile::Rectangle(r) => vec![r.corners().to_vec()],
            Profile::Polygon(p) => p.loops().to_vec(),
        }
    }
}
