// Sphere-facet and sphere-wall geometry that sees a sphere before it touches, so that reversible
// adhesion pulls it in across the gap as it does between spheres (YADE's Ig2_Facet_Sphere_ScGeom and
// Ig2_Wall_Sphere_ScGeom make a contact only in overlap). In overlap they give YADE's geometry
// (facets: shrinkFactor 0, walls: as YADE). mesocontact.scene.set_detection() puts them in place.
#pragma once
#include "MesoMeshContacts.hpp"
#include "PyChecks.hpp"
#include <core/Dispatching.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <atomic>

namespace yade {

#define MESO_SURFACE_GO                                                                                                                                        \
	bool go(const shared_ptr<Shape>&       cm1,                                                                                                            \
	        const shared_ptr<Shape>&       cm2,                                                                                                            \
	        const State&                   state1,                                                                                                         \
	        const State&                   state2,                                                                                                         \
	        const Vector3r&                shift2,                                                                                                         \
	        const bool&                    force,                                                                                                          \
	        const shared_ptr<Interaction>& c) override;                                                                                                    \
	bool goReverse(                                                                                                                                        \
	        const shared_ptr<Shape>&       cm1,                                                                                                            \
	        const shared_ptr<Shape>&       cm2,                                                                                                            \
	        const State&                   state1,                                                                                                         \
	        const State&                   state2,                                                                                                         \
	        const Vector3r&                shift2,                                                                                                         \
	        const bool&                    force,                                                                                                          \
	        const shared_ptr<Interaction>& c) override                                                                                                     \
	{                                                                                                                                                      \
		c->swapOrder();                                                                                                                                \
		return go(cm2, cm1, state2, state1, -shift2, force, c);                                                                                        \
	}

#define MESO_DETECTION_DOC                                                                                                                                     \
	"A new interaction is made when the gap between the sphere and the surface is below (interactionDetectionFactor - 1) times "                           \
	"the sphere's radius (as Ig2_Box_Sphere_ScGeom does); 1 makes contacts only in overlap, as YADE's functor does; a finite number "                      \
	">= 1 (checked on assignment). Pair with :yref:`Bo1_Sphere_Aabb.aabbEnlargeFactor` of the same value; "                                                \
	"mesocontact.scene.set_detection() sets both."

// The detection factor as last accepted; an assignment outside [1, inf) is undone and refused
// (a factor below 1 lets a sphere pass through the surface).
struct MesoDetectionCheck {
	Real valid = 1;
	void check(const char* functor, Real& factor);
};

class Ig2_Facet_Sphere_MesoScGeom : public IGeomFunctor {
	MesoDetectionCheck detection;
	std::atomic<bool>  vertexWarned { false }, overlapWarned { false };
	MesoMeshContacts   mesh; // where each contact with the facets lies now
	void               rebuildMesh(MesoMeshContacts& table, long iter);

protected:
	// The geometry of a sphere against a facet, made (isNew) or updated; false when the pair is not
	// in range and not yet an interaction. sixD: a new geometry is a ScGeom6D.
	bool geometry(
	        const Facet&,
	        Real                           radius,
	        const State&                   facet,
	        const State&                   sphere,
	        const Vector3r&                shift2,
	        bool                           force,
	        const shared_ptr<Interaction>& c,
	        bool                           sixD);

public:
	MESO_SURFACE_GO
	void postLoad(Ig2_Facet_Sphere_MesoScGeom&) { detection.check("Ig2_Facet_Sphere_MesoScGeom", interactionDetectionFactor); }
	void pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw) override { pychecks::ctorKeywords(*this, kw); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ig2_Facet_Sphere_MesoScGeom, IGeomFunctor,
		"Create/update a :yref:`ScGeom` of a :yref:`Facet` and a :yref:`Sphere` (yade-meso): YADE's "
		":yref:`Ig2_Facet_Sphere_ScGeom` (shrinkFactor 0, not hertzian) with a detection distance, for the pull-in of reversible "
		"adhesion. The normal points from the facet's nearest point to the sphere's centre; the overlap is the radius minus "
		"that distance (negative across a gap); radius1 = 2 radius, radius2 = radius. One contact per surface: a sphere over the "
		"edge two facets share (coplanar, or a convex edge), or over one facet near that edge, touches the mesh at one point, "
		"which only one facet holds (the nearer; of two at the same point the smaller id), as one large facet would; facets "
		"meeting in a valley touch the sphere at separate points and keep a contact each. A contact keeps its history across the "
		"mesh: the interaction that made it holds it while it travels over the edges and vertices to neighbouring facets of the same "
		"material (the facets that share its point), as one large facet would (:yref:`MesoPhys.meshFacet` tells where it lies); "
		"force and torque go to the holding facet. At a facet of another material the contact ends and that facet makes its own. "
		"Overlapping facets (a duplicated triangle) make one contact, with a warning.",
		((Real, interactionDetectionFactor, 1, Attr::triggerPostLoad, MESO_DETECTION_DOC)),
		/* ctor */,
		/* a wrong type named with the attribute, not Boost's "None.None(...)" */;
		pychecks::checked(_classObj, "interactionDetectionFactor", &Ig2_Facet_Sphere_MesoScGeom::interactionDetectionFactor);
		pychecks::guard(_classObj)
	);
	// clang-format on
	FUNCTOR2D(Facet, Sphere);
	DEFINE_FUNCTOR_ORDER_2D(Facet, Sphere);
};
REGISTER_SERIALIZABLE(Ig2_Facet_Sphere_MesoScGeom);

class Ig2_Facet_Sphere_MesoScGeom6D : public Ig2_Facet_Sphere_MesoScGeom {
public:
	MESO_SURFACE_GO
	// clang-format off
	YADE_CLASS_BASE_DOC(Ig2_Facet_Sphere_MesoScGeom6D, Ig2_Facet_Sphere_MesoScGeom,
		"As :yref:`Ig2_Facet_Sphere_MesoScGeom`, making a :yref:`ScGeom6D` (rolling and torsion), as "
		":yref:`Ig2_Facet_Sphere_ScGeom6D` does.")
	// clang-format on
	FUNCTOR2D(Facet, Sphere);
	DEFINE_FUNCTOR_ORDER_2D(Facet, Sphere);
};
REGISTER_SERIALIZABLE(Ig2_Facet_Sphere_MesoScGeom6D);

class Ig2_Wall_Sphere_MesoScGeom : public IGeomFunctor {
	MesoDetectionCheck detection;
	std::atomic<bool>  axisWarned { false };

public:
	MESO_SURFACE_GO
	void postLoad(Ig2_Wall_Sphere_MesoScGeom&) { detection.check("Ig2_Wall_Sphere_MesoScGeom", interactionDetectionFactor); }
	void pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw) override { pychecks::ctorKeywords(*this, kw); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ig2_Wall_Sphere_MesoScGeom, IGeomFunctor,
		"Create/update a :yref:`ScGeom` of a :yref:`Wall` and a :yref:`Sphere` (yade-meso): YADE's "
		":yref:`Ig2_Wall_Sphere_ScGeom` (not hertzian) with a detection distance, for the pull-in of reversible adhesion.",
		((Real, interactionDetectionFactor, 1, Attr::triggerPostLoad, MESO_DETECTION_DOC))
		((bool, noRatch, true, , "Avoid granular ratcheting (as :yref:`Ig2_Wall_Sphere_ScGeom.noRatch`).")),
		/* ctor */,
		;
		pychecks::checked(_classObj, "interactionDetectionFactor", &Ig2_Wall_Sphere_MesoScGeom::interactionDetectionFactor);
		pychecks::guard(_classObj)
	);
	// clang-format on
	FUNCTOR2D(Wall, Sphere);
	DEFINE_FUNCTOR_ORDER_2D(Wall, Sphere);
};
REGISTER_SERIALIZABLE(Ig2_Wall_Sphere_MesoScGeom);

} // namespace yade
