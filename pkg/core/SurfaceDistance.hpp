// The point of a triangle nearest to a point: what a sphere "sees" of a facet. Used by the facet
// geometry with a detection distance (pkg/yade/MesoSurfaceGeom.cpp). Header-only; Eigen, no YADE.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>

namespace meso {

// Nearest point of the segment (a, b) to p; a when the segment is a point.
inline Eigen::Vector3d nearestOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	const Eigen::Vector3d ab = b - a;
	const double          l2 = ab.squaredNorm();
	if (!(l2 > 0)) return a;
	return a + std::clamp(ab.dot(p - a) / l2, 0.0, 1.0) * ab;
}

// Nearest point of the triangle (a, b, c) to p, by the Voronoi region of p: a vertex, an edge or the
// face. A degenerate triangle (two vertices coincident, or all three on a line to within 1e-10 rad,
// as in slivers of meshes from STL) is the union of its edges: the nearest point of the nearest edge,
// since the regions' divisions would be 0/0 there.
inline Eigen::Vector3d nearestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
	const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
	if (!(ab.cross(ac).squaredNorm() > 1e-20 * ab.squaredNorm() * ac.squaredNorm())) {
		const Eigen::Vector3d e[3] = { nearestOnSegment(p, a, b), nearestOnSegment(p, b, c), nearestOnSegment(p, c, a) };
		int                   best = 0;
		for (int k = 1; k < 3; ++k)
			if ((p - e[k]).squaredNorm() < (p - e[best]).squaredNorm()) best = k;
		return e[best];
	}
	const double d1 = ab.dot(ap), d2 = ac.dot(ap);
	if (d1 <= 0 && d2 <= 0) return a;
	const Eigen::Vector3d bp = p - b;
	const double          d3 = ab.dot(bp), d4 = ac.dot(bp);
	if (d3 >= 0 && d4 <= d3) return b;
	const double vc = d1 * d4 - d3 * d2;
	if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab; // edge ab
	const Eigen::Vector3d cp = p - c;
	const double          d5 = ab.dot(cp), d6 = ac.dot(cp);
	if (d6 >= 0 && d5 <= d6) return c;
	const double vb = d5 * d2 - d1 * d6;
	if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac; // edge ac
	const double va = d3 * d6 - d5 * d4;
	if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b); // edge bc
	const double denom = va + vb + vc;
	if (!(denom > 0)) return a;                       // all three vertices coincide
	return a + (vb / denom) * ab + (vc / denom) * ac; // inside the face
}

// Whether p (a point of the triangle) lies on one of its edges, within tol: only such a point can be
// another facet's too, unless the facets overlap.
inline bool onTriangleEdge(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double tol)
{
	const double t2 = tol * tol;
	return (nearestOnSegment(p, a, b) - p).squaredNorm() <= t2 || (nearestOnSegment(p, b, c) - p).squaredNorm() <= t2
	        || (nearestOnSegment(p, c, a) - p).squaredNorm() <= t2;
}

// Whether a facet's contact at p (its nearest point to a sphere's centre) is left to another facet
// (a, b, c) of the same sphere: only if p lies on that facet too (within tol), which then holds the
// contact at its own nearest point q: nearer when q is not p (a sphere over one facet near the edge
// it shares with this one), or the same point (a sphere over the shared edge or a convex edge),
// where the smaller id keeps it. One contact per surface that is flat or convex there, as one large
// facet would give; facets meeting in a valley touch the sphere at separate points and keep both.
inline bool leftToOtherFacet(
        const Eigen::Vector3d& p,
        int                    id,
        const Eigen::Vector3d& centre,
        const Eigen::Vector3d& a,
        const Eigen::Vector3d& b,
        const Eigen::Vector3d& c,
        int                    otherId,
        double                 tol)
{
	if ((nearestOnTriangle(p, a, b, c) - p).squaredNorm() > tol * tol) return false;
	const Eigen::Vector3d q = nearestOnTriangle(centre, a, b, c);
	return (q - p).squaredNorm() > tol * tol || otherId < id;
}

} // namespace meso
