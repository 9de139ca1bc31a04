#include "MesoSurfaceGeom.hpp"
#include "../core/SurfaceDistance.hpp"
#include "PyRelease.hpp"

#include <core/BodyContainer.hpp>
#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((Ig2_Facet_Sphere_MesoScGeom)(Ig2_Facet_Sphere_MesoScGeom6D)(Ig2_Wall_Sphere_MesoScGeom));

namespace {
	Eigen::Vector3d toEigen(const Vector3r& v) { return Eigen::Vector3d(double(v[0]), double(v[1]), double(v[2])); }
	Vector3r        fromEigen(const Eigen::Vector3d& v) { return Vector3r(v[0], v[1], v[2]); }

	// Fills a made (isNew) or present geometry; the normal points from the surface to the sphere.
	void
	fill(ScGeom&                        g,
	     const State&                   s1,
	     const State&                   s2,
	     Scene*                         scene,
	     const shared_ptr<Interaction>& c,
	     const Vector3r&                normal,
	     Real                           overlap,
	     Real                           radius1,
	     Real                           radius2,
	     const Vector3r&                contactPoint,
	     bool                           isNew,
	     const Vector3r&                shift2,
	     bool                           noRatch)
	{
		g.contactPoint     = contactPoint;
		g.penetrationDepth = overlap;
		g.radius1          = radius1;
		g.radius2          = radius2;
		g.precompute(s1, s2, scene, c, normal, isNew, shift2, noRatch);
	}
} // namespace

void MesoDetectionCheck::check(const char* functor, Real& factor)
{
	if (factor >= 1 && std::isfinite(factor)) {
		valid = factor;
		return;
	}
	std::ostringstream msg;
	msg.precision(17);
	msg << functor << ".interactionDetectionFactor = " << factor
	    << " is invalid: must be a finite number >= 1 (1: contacts only in overlap; below 1 a sphere passes through the surface)";
	factor = valid;
	throw std::invalid_argument(msg.str());
}

namespace {
	// A geometry this functor can update: of its own class (a ScGeom6D where it makes one). Another
	// class (restored or assigned from Python) is replaced by a new one, not cast to the wrong type.
	bool fits(const shared_ptr<IGeom>& geom, bool sixD)
	{
		const int ix = geom->getClassIndex();
		return ix == ScGeom6D::getClassIndexStatic() || (!sixD && ix == ScGeom::getClassIndexStatic());
	}
}

namespace {
	// How near two points computed in two facets' frames count as one (their rounding, with margin).
	double edgeTolerance(Real radius, const Vector3r& centre) { return 1e-9 * double(radius + centre.norm()); }

	// The facet's vertices in global coordinates.
	void corners(const Facet& f, const State& s, Eigen::Vector3d (&out)[3])
	{
		const Matrix3r r = s.ori.toRotationMatrix();
		for (int k = 0; k < 3; ++k)
			out[k] = toEigen(s.pos + r * f.vertices[k]);
	}
}

bool Ig2_Facet_Sphere_MesoScGeom::leftToOtherFacet(const Vector3r& p, const Vector3r& centre, Real radius, const Vector3r& shift2, const Interaction& c) const
{
	const shared_ptr<Body>& b1       = Body::byId(c.getId1(), scene);
	const bool              facet1   = b1 && dynamic_cast<const Facet*>(b1->shape.get());
	const Body::id_t        facetId  = facet1 ? c.getId1() : c.getId2();
	const Body::id_t        sphereId = facet1 ? c.getId2() : c.getId1();
	const shared_ptr<Body>& sphere   = Body::byId(sphereId, scene);
	if (!sphere) return false;
	const double tol = edgeTolerance(radius, centre);
	for (const auto& [otherId, other] : sphere->intrs) {
		if (otherId == facetId || !other) continue;
		const shared_ptr<Body>& b = Body::byId(otherId, scene);
		const auto*             f = b ? dynamic_cast<const Facet*>(b->shape.get()) : nullptr;
		if (!f) continue;
		// The sphere as the other facet sees it (periodic cells: that interaction's own image).
		Vector3r shift = Vector3r::Zero();
		if (scene->isPeriodic) shift = (other->getId1() == sphereId ? -1. : 1.) * scene->cell->intrShiftPos(other->cellDist);
		Eigen::Vector3d v[3];
		corners(*f, *b->state, v);
		const Eigen::Vector3d move = toEigen(shift - shift2);
		if (meso::leftToOtherFacet(toEigen(p) + move, facetId, toEigen(centre) + move, v[0], v[1], v[2], otherId, tol)) return true;
	}
	return false;
}

bool Ig2_Facet_Sphere_MesoScGeom::geometry(
        const Facet& facet, Real radius, const State& s1, const State& s2, const Vector3r& shift2, bool force, const shared_ptr<Interaction>& c, bool sixD)
{
	// In the facet's own frame (its vertices are stored there), the centre's nearest point of the triangle.
	const Matrix3r toGlobal = s1.ori.toRotationMatrix();
	const Vector3r centre   = s2.pos + shift2;
	const Vector3r local    = toGlobal.transpose() * (centre - s1.pos);
	const auto&    v        = facet.vertices;
	if (!(v[0].allFinite() && v[1].allFinite() && v[2].allFinite() && s1.pos.allFinite())) [[unlikely]] {
		if (!vertexWarned.exchange(true)) // no exception may leave YADE's OpenMP loop
			std::cerr << "WARNING Ig2_Facet_Sphere_MesoScGeom: facet #" << (c->getId1()) << " has a vertex or a position that is not "
			          << "finite (NaN or inf): it makes no contacts. (Warned once.)" << std::endl;
		return false;
	}
	const Vector3r nearest = fromEigen(meso::nearestOnTriangle(toEigen(local), toEigen(v[0]), toEigen(v[1]), toEigen(v[2])));
	Vector3r       branch  = local - nearest;
	const Real     dist    = branch.norm();
	const Real     overlap = radius - dist;
	if (!c->isReal() && !force && !(overlap > -(interactionDetectionFactor - 1) * radius)) return false;
	// One contact per surface: a point on an edge may be another facet's, which then holds it.
	if (meso::onTriangleEdge(toEigen(nearest), toEigen(v[0]), toEigen(v[1]), toEigen(v[2]), edgeTolerance(radius, centre))
	    && leftToOtherFacet(s1.pos + toGlobal * nearest, centre, radius, shift2, *c))
		return false;
	if (dist > 1e-12 * radius) branch /= dist;
	else { // the centre on the facet: the facet's own normal, toward the side the sphere came from
		branch = (v[1] - v[0]).cross(v[2] - v[1]).normalized();
		if (c->geom && fits(c->geom, false) && YADE_PTR_CAST<ScGeom>(c->geom)->normal.dot(toGlobal * branch) < 0) branch = -branch;
	}
	const bool isNew = !c->geom || !fits(c->geom, sixD);
	if (c->geom && isNew) pyrelease::releaseIfHeld(c->geom);
	if (isNew) c->geom = sixD ? shared_ptr<ScGeom>(new ScGeom6D()) : shared_ptr<ScGeom>(new ScGeom());
	ScGeom&        g      = *YADE_PTR_CAST<ScGeom>(c->geom);
	const Vector3r normal = toGlobal * branch;
	// As YADE's: the contact point halfway into the overlap.
	fill(g, s1, s2, scene, c, normal, overlap, 2 * radius, radius, centre - (radius - 0.5 * overlap) * normal, isNew, shift2, false);
	if (sixD) static_cast<ScGeom6D&>(g).precomputeRotations(s1, s2, isNew, false);
	return true;
}

bool Ig2_Facet_Sphere_MesoScGeom::go(
        const shared_ptr<Shape>&       cm1,
        const shared_ptr<Shape>&       cm2,
        const State&                   s1,
        const State&                   s2,
        const Vector3r&                shift2,
        const bool&                    force,
        const shared_ptr<Interaction>& c)
{
	return geometry(static_cast<const Facet&>(*cm1), static_cast<const Sphere&>(*cm2).radius, s1, s2, shift2, force, c, false);
}

bool Ig2_Facet_Sphere_MesoScGeom6D::go(
        const shared_ptr<Shape>&       cm1,
        const shared_ptr<Shape>&       cm2,
        const State&                   s1,
        const State&                   s2,
        const Vector3r&                shift2,
        const bool&                    force,
        const shared_ptr<Interaction>& c)
{
	return geometry(static_cast<const Facet&>(*cm1), static_cast<const Sphere&>(*cm2).radius, s1, s2, shift2, force, c, true);
}

bool Ig2_Wall_Sphere_MesoScGeom::go(
        const shared_ptr<Shape>&       cm1,
        const shared_ptr<Shape>&       cm2,
        const State&                   s1,
        const State&                   s2,
        const Vector3r&                shift2,
        const bool&                    force,
        const shared_ptr<Interaction>& c)
{
	const Wall& wall   = static_cast<const Wall&>(*cm1);
	const Real  radius = static_cast<const Sphere&>(*cm2).radius;
	const int   ax     = wall.axis;
	if (ax < 0 || ax > 2) [[unlikely]] { // YADE accepts any integer; no exception may leave its OpenMP loop
		if (!axisWarned.exchange(true))
			std::cerr << "WARNING Ig2_Wall_Sphere_MesoScGeom: Wall.axis = " << ax << " is invalid: must be 0, 1 or 2 (x, y, z); the wall "
			          << "makes no contacts. (Warned once.)" << std::endl;
		return false;
	}
	const Real dist    = s2.pos[ax] + shift2[ax] - s1.pos[ax]; // signed, centre to the wall's plane
	const Real overlap = radius - math::abs(dist);
	if (!c->isReal() && !force && !(overlap > -(interactionDetectionFactor - 1) * radius)) return false;
	Vector3r normal  = Vector3r::Zero();
	normal[ax]       = wall.sense == 0 ? (dist > 0 ? 1. : -1.) : (wall.sense > 0 ? 1. : -1.);
	const bool isNew = !c->geom || !fits(c->geom, false);
	if (c->geom && isNew) pyrelease::releaseIfHeld(c->geom);
	if (isNew) c->geom = shared_ptr<ScGeom>(new ScGeom());
	// As YADE's: the contact point is the centre projected onto the wall, and radius1 is the sphere's
	// (the law itself takes a12 = 2a at walls).
	Vector3r onWall = s2.pos + shift2;
	onWall[ax]      = s1.pos[ax];
	fill(*YADE_PTR_CAST<ScGeom>(c->geom), s1, s2, scene, c, normal, overlap, radius, radius, onWall, isNew, shift2, noRatch);
	return true;
}

} // namespace yade
