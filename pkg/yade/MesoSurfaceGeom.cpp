#include "MesoSurfaceGeom.hpp"
#include "../core/SurfaceDistance.hpp"
#include "MesoContact.hpp"
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

namespace {
	// A facet of the sphere's interactions with its corners in this pair's image of the sphere.
	struct FacetView {
		Body::id_t      id   = -1;
		const Body*     body = nullptr;
		Eigen::Vector3d v[3];
	};

	// The facet `id` of the sphere's interaction `other` (real or not) as this pair (shift2) sees it.
	bool facetView(Scene* scene, Body::id_t id, const Interaction& other, Body::id_t sphereId, const Vector3r& shift2, FacetView& out)
	{
		const shared_ptr<Body>& b = Body::byId(id, scene);
		const auto*             f = b ? dynamic_cast<const Facet*>(b->shape.get()) : nullptr;
		if (!f) return false;
		// The sphere as the other facet sees it (periodic cells: that interaction's own image).
		Vector3r shift = Vector3r::Zero();
		if (scene->isPeriodic) shift = (other.getId1() == sphereId ? -1. : 1.) * scene->cell->intrShiftPos(other.cellDist);
		corners(*f, *b->state, out.v);
		const Eigen::Vector3d move = toEigen(shift - shift2);
		for (Eigen::Vector3d& corner : out.v)
			corner -= move;
		out.id   = id;
		out.body = b.get();
		return true;
	}

	Eigen::Vector3d nearestOn(const FacetView& f, const Eigen::Vector3d& centre) { return meso::nearestOnTriangle(centre, f.v[0], f.v[1], f.v[2]); }
	bool            onEdge(const FacetView& f, const Eigen::Vector3d& p, double tol) { return meso::onTriangleEdge(p, f.v[0], f.v[1], f.v[2], tol); }
}

namespace {
	// The sphere's facets, each facetView()'d, to f (stops when f returns true); true if it did.
	template <class F> bool anyFacet(Scene* scene, const Body& sphere, Body::id_t sphereId, const Vector3r& shift2, Body::id_t skip, F&& f)
	{
		for (const auto& [otherId, other] : sphere.intrs) {
			FacetView view;
			if (otherId == skip || !other || !facetView(scene, otherId, *other, sphereId, shift2, view)) continue;
			if (f(view)) return true;
		}
		return false;
	}

	enum class Which { Any, Other }; // which facets may take a contact: any, or of another material than the one it is on

	// Whether the contact point p of facet `from` is another facet's (meso::leftToOtherFacet).
	bool leavesTo(
	        Scene*                 scene,
	        const FacetView&       from,
	        const Eigen::Vector3d& p,
	        const Eigen::Vector3d& centre,
	        double                 tol,
	        const Body&            sphere,
	        Body::id_t             sphereId,
	        const Vector3r&        shift2,
	        Which                  which,
	        std::atomic<bool>&     overlapWarned)
	{
		const bool interior = !onEdge(from, p, tol);
		return anyFacet(scene, sphere, sphereId, shift2, from.id, [&](const FacetView& other) {
			const bool same = other.body->material == from.body->material;
			if (which == Which::Other && same) return false;
			if (!meso::leftToOtherFacet(p, from.id, centre, other.v[0], other.v[1], other.v[2], other.id, tol)) return false;
			if (interior && !overlapWarned.exchange(true)) // a point inside one facet lies on another: they overlap
				std::cerr << "WARNING Ig2_Facet_Sphere_MesoScGeom: facets #" << from.id << " and #" << other.id << " overlap where sphere #"
				          << sphereId << " touches them (a duplicated triangle, as STL exports may hold?): one contact is made, held by "
				          << "the facet of the smaller id. (Warned once.)" << std::endl;
			return true;
		});
	}

	// From facet cur, the contact followed over the sphere's facets of the same material, each hop to
	// the facet that holds the point (meso::leftToOtherFacet), to where the surface is nearest the
	// sphere: the facet the contact lies on now, and p, its point.
	FacetView
	walk(Scene*                 scene,
	     FacetView              cur,
	     const Eigen::Vector3d& centre,
	     double                 tol,
	     const Body&            sphere,
	     Body::id_t             sphereId,
	     const Vector3r&        shift2,
	     Eigen::Vector3d&       p)
	{
		p = nearestOn(cur, centre);
		// Each hop goes to a strictly nearer point, or to the same point on a facet of smaller id: no cycle.
		for (std::size_t hop = 0; hop <= sphere.intrs.size() && onEdge(cur, p, tol); ++hop) {
			const bool moved = anyFacet(scene, sphere, sphereId, shift2, cur.id, [&](const FacetView& next) {
				if (next.body->material != cur.body->material
				    || !meso::leftToOtherFacet(p, cur.id, centre, next.v[0], next.v[1], next.v[2], next.id, tol))
					return false;
				cur = next;
				p   = nearestOn(cur, centre);
				return true;
			});
			if (!moved) break;
		}
		return cur;
	}
} // namespace

void Ig2_Facet_Sphere_MesoScGeom::rebuildMesh(MesoMeshContacts& table, long iter)
{
	// Runs before any facet contact of this step is processed (MesoMeshContacts::beginStep): only
	// the ids of other interactions are read first, their state only where both bodies are ours.
	for (const shared_ptr<Interaction>& I : *scene->interactions) {
		const shared_ptr<Body>& b1 = Body::byId(I->getId1(), scene);
		const shared_ptr<Body>& b2 = Body::byId(I->getId2(), scene);
		if (!b1 || !b2 || !dynamic_cast<const Facet*>(b1->shape.get()) || !dynamic_cast<const Sphere*>(b2->shape.get()) || !I->isReal()) continue;
		const auto* phys = dynamic_cast<const MesoPhys*>(I->phys.get());
		const int   at   = phys && phys->geometry.meshFacet >= 0 ? phys->geometry.meshFacet : I->getId1();
		table.put(I->getId2(), I->getId1(), at, iter - 1);
	}
}

bool Ig2_Facet_Sphere_MesoScGeom::geometry(
        const Facet& facet, Real radius, const State& s1, const State& s2, const Vector3r& shift2, bool force, const shared_ptr<Interaction>& c, bool sixD)
{
	const long iter = scene->iter;
	mesh.beginStep(scene, iter, [this](MesoMeshContacts& table, long it) { rebuildMesh(table, it); });
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
	const Vector3r   nearest  = fromEigen(meso::nearestOnTriangle(toEigen(local), toEigen(v[0]), toEigen(v[1]), toEigen(v[2])));
	Vector3r         branch   = local - nearest;
	Real             dist     = branch.norm();
	Real             overlap  = radius - dist;
	const bool       real     = c->isReal();
	const Body::id_t facetId  = c->getId1();
	const Body::id_t sphereId = c->getId2();
	if (!real && !force && !(overlap > -(interactionDetectionFactor - 1) * radius)) return false;
	const double            tol    = edgeTolerance(radius, centre);
	const shared_ptr<Body>& sphere = Body::byId(sphereId, scene);
	FacetView               self;
	self.id   = facetId;
	self.body = Body::byId(facetId, scene).get();
	corners(facet, s1, self.v);
	const Eigen::Vector3d centreE = toEigen(centre), nearestE = toEigen(s1.pos + toGlobal * nearest);
	const State*          on = &s1; // the state of the facet the contact lies on
	Vector3r              normal;
	if (!real) {
		// A new contact: only where no other facet holds the point, nor one of the sphere's contacts stands.
		if (sphere && leavesTo(scene, self, nearestE, centreE, tol, *sphere, sphereId, shift2, Which::Any, overlapWarned)) return false;
		static thread_local std::vector<MesoMeshContacts::Entry> others; // kept: no allocation per call
		if (sphere) mesh.others(sphereId, facetId, iter, others);
		if (sphere)
			for (const MesoMeshContacts::Entry& e : others) {
				FacetView        from;
				const Body::id_t start = sphere->intrs.count(e.at) ? e.at : e.holder;
				const auto       found = sphere->intrs.find(start);
				if (found == sphere->intrs.end() || !found->second || !facetView(scene, start, *found->second, sphereId, shift2, from))
					continue;
				Eigen::Vector3d p;
				if (walk(scene, from, centreE, tol, *sphere, sphereId, shift2, p).id == facetId) return false;
			}
		mesh.record(sphereId, facetId, facetId, iter);
	} else if (sphere) {
		// A contact goes on where the surface is nearest the sphere, across the mesh's edges (walk()).
		static thread_local std::vector<MesoMeshContacts::Entry> others; // kept: no allocation per call
		const Body::id_t                                         startId = mesh.at(sphereId, facetId, iter, others);
		FacetView                                                cur     = self;
		if (startId != facetId) {
			const auto found = sphere->intrs.find(startId);
			if (found != sphere->intrs.end() && found->second) facetView(scene, startId, *found->second, sphereId, shift2, cur);
		}
		if (cur.id != facetId || meso::onTriangleEdge(toEigen(nearest), toEigen(v[0]), toEigen(v[1]), toEigen(v[2]), tol)) {
			Eigen::Vector3d p;
			cur = walk(scene, cur, centreE, tol, *sphere, sphereId, shift2, p);
			// At a facet of another material the contact ends and that facet makes its own.
			if (onEdge(cur, p, tol) && leavesTo(scene, cur, p, centreE, tol, *sphere, sphereId, shift2, Which::Other, overlapWarned)) {
				mesh.forget(sphereId, facetId);
				return false;
			}
			if (cur.id != facetId) {
				const Eigen::Vector3d b = centreE - p;
				dist                    = b.norm();
				overlap                 = radius - dist;
				branch                  = fromEigen(b);
				on                      = cur.body->state.get();
			}
		}
		// Two contacts met on one facet: out of a fold, where this one's nearest point ceased to be a
		// nearest point of the surface. The one that came ends; of two that came in one step (or
		// stood on one facet since), the holder of the smaller id goes on.
		for (const MesoMeshContacts::Entry& e : others)
			if (e.at == cur.id && (startId != cur.id || e.holder < facetId)) {
				mesh.forget(sphereId, facetId);
				return false;
			}
		if (cur.id != startId)
			if (auto* phys = dynamic_cast<MesoPhys*>(c->phys.get())) phys->geometry.meshFacet = cur.id == facetId ? -1 : cur.id;
		mesh.record(sphereId, facetId, cur.id, iter);
		if (on != &s1) { // the geometry on another facet, computed in global coordinates
			if (dist > 1e-12 * radius) normal = branch / dist;
			else {
				const Eigen::Vector3d n = (cur.v[1] - cur.v[0]).cross(cur.v[2] - cur.v[1]).normalized();
				normal                  = fromEigen(n);
				if (fits(c->geom, false) && YADE_PTR_CAST<ScGeom>(c->geom)->normal.dot(normal) < 0) normal = -normal;
			}
		}
	}
	if (on == &s1) {
		if (dist > 1e-12 * radius) branch /= dist;
		else { // the centre on the facet: the facet's own normal, toward the side the sphere came from
			branch = (v[1] - v[0]).cross(v[2] - v[1]).normalized();
			if (c->geom && fits(c->geom, false) && YADE_PTR_CAST<ScGeom>(c->geom)->normal.dot(toGlobal * branch) < 0) branch = -branch;
		}
		normal = toGlobal * branch;
	}
	const bool isNew = !c->geom || !fits(c->geom, sixD);
	if (c->geom && isNew) pyrelease::releaseIfHeld(c->geom);
	if (isNew) c->geom = sixD ? shared_ptr<ScGeom>(new ScGeom6D()) : shared_ptr<ScGeom>(new ScGeom());
	ScGeom& g = *YADE_PTR_CAST<ScGeom>(c->geom);
	// As YADE's: the contact point halfway into the overlap.
	fill(g, *on, s2, scene, c, normal, overlap, 2 * radius, radius, centre - (radius - 0.5 * overlap) * normal, isNew, shift2, false);
	if (sixD) static_cast<ScGeom6D&>(g).precomputeRotations(*on, s2, isNew, false);
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
