// The nearest point of a triangle against a brute-force search over a fine grid of the triangle:
// no grid point may be nearer than the returned point, and the returned point lies on the triangle.
#include "SurfaceDistance.hpp"
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <random>

using V = Eigen::Vector3d;

namespace {
// Barycentric grid of n x n sub-triangles: the brute-force nearest distance (to ~edge/n).
double bruteDistance(const V& p, const V& a, const V& b, const V& c, int n)
{
	double best = 1e300;
	for (int i = 0; i <= n; ++i)
		for (int j = 0; i + j <= n; ++j) {
			const V q = a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
			best      = std::min(best, (p - q).norm());
		}
	return best;
}
// Is q on the triangle (a, b, c)? Its barycentric coordinates in [0, 1], its offset from the plane ~0.
bool onTriangle(const V& q, const V& a, const V& b, const V& c)
{
	const V      n = (b - a).cross(c - a);
	const double A = n.norm();
	const double u = (b - q).cross(c - q).dot(n) / (A * A), v = (c - q).cross(a - q).dot(n) / (A * A);
	const double w = 1 - u - v, off = std::abs((q - a).dot(n)) / A;
	const double tol = 1e-12;
	return u > -tol && v > -tol && w > -tol && off < tol * (b - a).norm();
}
} // namespace

TEST(NearestOnTriangle, NeverFartherThanAnyPointOfTheTriangle)
{
	std::mt19937                           rng(7);
	std::uniform_real_distribution<double> u(-1.0, 1.0);
	const int                              n = 200;
	for (int k = 0; k < 300; ++k) {
		const V a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
		const V p(2 * u(rng), 2 * u(rng), 2 * u(rng));
		const V q = meso::nearestOnTriangle(p, a, b, c);
		ASSERT_TRUE(onTriangle(q, a, b, c)) << "case " << k;
		const double edge = std::max({ (b - a).norm(), (c - a).norm(), (c - b).norm() });
		// The grid's nearest point is at most edge/n from the true one: nothing on the grid is nearer.
		EXPECT_LE((p - q).norm(), bruteDistance(p, a, b, c, n) + 1e-12) << "case " << k;
		EXPECT_GE((p - q).norm(), bruteDistance(p, a, b, c, n) - edge / n) << "case " << k;
	}
}

TEST(NearestOnTriangle, EachRegion)
{
	const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
	EXPECT_TRUE(meso::nearestOnTriangle(V(0.2, 0.3, 0.5), a, b, c).isApprox(V(0.2, 0.3, 0))); // face
	EXPECT_TRUE(meso::nearestOnTriangle(V(-1, -1, 0.2), a, b, c).isApprox(a));                // vertex a
	EXPECT_TRUE(meso::nearestOnTriangle(V(2, -0.5, 0), a, b, c).isApprox(b));                 // vertex b
	EXPECT_TRUE(meso::nearestOnTriangle(V(-0.1, 3, 0), a, b, c).isApprox(c));                 // vertex c
	EXPECT_TRUE(meso::nearestOnTriangle(V(0.5, -2, 1), a, b, c).isApprox(V(0.5, 0, 0)));      // edge ab
	EXPECT_TRUE(meso::nearestOnTriangle(V(-2, 0.5, 1), a, b, c).isApprox(V(0, 0.5, 0)));      // edge ac
	EXPECT_TRUE(meso::nearestOnTriangle(V(1, 1, -1), a, b, c).isApprox(V(0.5, 0.5, 0)));      // edge bc
}

// Slivers of meshes from STL: two vertices coincident, or all three on a line. The nearest point is
// that of the segment they span, found by brute force over the segment.
TEST(NearestOnTriangle, DegenerateTrianglesAreTheirEdges)
{
	auto segmentDistance = [](const V& p, const V& a, const V& b) {
		double best = 1e300;
		for (int i = 0; i <= 100000; ++i)
			best = std::min(best, (p - (a + (i / 100000.0) * (b - a))).norm());
		return best;
	};
	const V a(0, 0, 0), b(1, 0, 0), mid(0.5, 0, 0);
	const V points[] = { V(0.3, 0.4, 0.2), V(-0.5, 0.1, 0), V(1.7, -0.2, 0.3), V(0.5, 0, 1) };
	for (const V& p : points) {
		for (const auto& [v0, v1, v2] :
		     { std::make_tuple(a, a, b), std::make_tuple(a, b, b), std::make_tuple(b, a, a), std::make_tuple(a, mid, b), std::make_tuple(mid, b, a) }) {
			const V q = meso::nearestOnTriangle(p, v0, v1, v2);
			ASSERT_TRUE(q.allFinite());
			EXPECT_NEAR(q.y(), 0, 1e-15);
			EXPECT_NEAR(q.z(), 0, 1e-15);
			EXPECT_NEAR((p - q).norm(), segmentDistance(p, a, b), 1e-5);
		}
		EXPECT_TRUE(meso::nearestOnTriangle(p, a, a, a).isApprox(a)); // a point
	}
}

// One contact per surface (meso::leftToOtherFacet): which facets of a mesh keep a sphere's contact.
namespace {
struct Tri {
	V   a, b, c;
	int id;
};
// The facets that keep the contact of a sphere at `centre`: those whose nearest point no other
// facet in range takes (each facet's own view, as the functor decides it).
std::vector<int> keepers(const V& centre, const std::vector<Tri>& mesh, double range)
{
	std::vector<int> kept;
	for (const Tri& f : mesh) {
		const V p = meso::nearestOnTriangle(centre, f.a, f.b, f.c);
		if ((centre - p).norm() > range) continue;
		bool left = false;
		for (const Tri& g : mesh)
			if (g.id != f.id && meso::leftToOtherFacet(p, f.id, centre, g.a, g.b, g.c, g.id, 1e-12)) left = true;
		if (!left) kept.push_back(f.id);
	}
	return kept;
}
} // namespace

TEST(LeftToOtherFacet, OneContactOverAFlatSquareOfTwoTriangles)
{
	// The unit square z = 0 as two triangles sharing the diagonal (0,0)-(1,1), as geom.facetBox makes it.
	const std::vector<Tri> square = { { V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), 7 }, { V(0, 0, 0), V(1, 1, 0), V(0, 1, 0), 3 } };
	EXPECT_EQ(keepers(V(0.5, 0.5, 0.1), square, 0.2), std::vector<int>({ 3 }));         // over the diagonal: the smaller id
	EXPECT_EQ(keepers(V(0.6, 0.5, 0.1), square, 0.2), std::vector<int>({ 7 }));         // over 7 near the diagonal: 7 only
	EXPECT_EQ(keepers(V(0.5, 0.6, 0.1), square, 0.2), std::vector<int>({ 3 }));         // over 3 near it: 3 only
	EXPECT_EQ(keepers(V(0.5 + 1e-13, 0.5, 0.1), square, 0.2), std::vector<int>({ 3 })); // within rounding of the edge: one
	EXPECT_EQ(keepers(V(0, 0, 0.1), square, 0.2), std::vector<int>({ 3 }));             // over the shared vertex
	EXPECT_EQ(keepers(V(1.05, 0.5, 0.05), square, 0.2), std::vector<int>({ 7 }));       // beside the outer edge: 7's edge only
}

TEST(LeftToOtherFacet, ConvexEdgeOnceValleyTwice)
{
	// Two faces meeting at the x axis at 90 degrees: y = 0 (z >= 0) and z = 0 (y >= 0).
	const Tri              wallY0 { V(0, 0, 0), V(2, 0, 0), V(0, 0, 2), 1 }, floorZ0 { V(0, 0, 0), V(0, 2, 0), V(2, 0, 0), 2 };
	const std::vector<Tri> corner = { wallY0, floorZ0 };
	EXPECT_EQ(keepers(V(1, 0.1, 0.1), corner, 0.2), std::vector<int>({ 1, 2 })); // in the valley: a contact on each face
	EXPECT_EQ(keepers(V(1, -0.1, -0.1), corner, 0.2), std::vector<int>({ 1 }));  // outside the ridge: one, on the edge
	EXPECT_EQ(keepers(V(1, -0.1, 0.05), corner, 0.2), std::vector<int>({ 1 }));  // against the wall's face from outside
	// A facet far away keeps its own contact (the sphere's point is not on it).
	const std::vector<Tri> apart = { floorZ0, { V(0, 0, 0.3), V(0, 2, 0.3), V(2, 0, 0.3), 5 } };
	EXPECT_EQ(keepers(V(0.5, 0.5, 0.15), apart, 0.2), std::vector<int>({ 2, 5 }));
}

TEST(OnTriangleEdge, EdgesAndVerticesNotTheFace)
{
	const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
	EXPECT_TRUE(meso::onTriangleEdge(V(0.5, 0, 0), a, b, c, 1e-12));    // edge ab
	EXPECT_TRUE(meso::onTriangleEdge(V(0.5, 0.5, 0), a, b, c, 1e-12));  // edge bc
	EXPECT_TRUE(meso::onTriangleEdge(c, a, b, c, 1e-12));               // a vertex
	EXPECT_FALSE(meso::onTriangleEdge(V(0.2, 0.2, 0), a, b, c, 1e-12)); // the face
	EXPECT_FALSE(meso::onTriangleEdge(V(0.5, 1e-9, 0), a, b, c, 1e-12));
	EXPECT_TRUE(meso::onTriangleEdge(V(0.5, 1e-13, 0), a, b, c, 1e-12));
}
