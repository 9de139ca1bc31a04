// YADE adapter of the meso-particle contact law: Material (parameters), IPhys (per-contact
// history), Ip2 (mixing) and Law2 (calls the YADE-free core in pkg/core and applies forces).
#pragma once
#include "../core/NormalLaw.hpp"
#include "../core/Tangential.hpp"
#include "MesoNeighbourSums.hpp"
#include "PyChecks.hpp"

#include <core/Dispatching.hpp>
#include <pkg/common/ElastMat.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

#include <boost/serialization/version.hpp>

#include <atomic>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>

namespace yade {

// A number of MesoParamTable.hpp as a MesoMat attribute; every assignment is validated (postLoad).
#define MESO_MAT_ATTR(name, def, unit, ok, rule, mix, dest, doc) ((Real, name, def, Attr::triggerPostLoad, doc " [" unit "]."))
// An added parameter: saved by serialize(MesoMat) below, after the rest, so that older files load.
#define MESO_MAT_ADDED_ATTR(name, def, unit, ok, rule, mix, dest, doc) ((Real, name, def, (Attr::triggerPostLoad | Attr::noSave), doc " [" unit "]."))

class MesoMat : public FrictMat {
	meso::MaterialParams valid;               // the attributes parsed and validated: what contacts are made from
	bool                 deferChecks = false; // set while several keywords are applied before one check
	meso::MaterialParams parse() const;       // throws std::invalid_argument naming the parameter
	unsigned long        revisionCount = 0;   // counts accepted changes: contacts made before keep the parameters they had

public:
	virtual ~MesoMat() = default;
	// Validated parameters; never throws (the Ip2 runs inside YADE's OpenMP loop).
	const meso::MaterialParams& params() const { return valid; }
	unsigned long               revision() const { return revisionCount; }
	void                        postLoad(MesoMat&);
	Real                        getFrictionAngle() const { return frictionAngle; }
	void                        setFrictionAngle(Real a); // validated, like the attributes below
	Real                        getDensity() const { return density; }
	void                        setDensity(Real d);
	Real                        getYoung() const { return young; }
	void                        setYoung(Real y);
	Real                        getPoisson() const { return poisson; }
	void                        setPoisson(Real p);
	std::string                 getLabel() const { return label; }
	void                        setLabel(std::string l) { label = std::move(l); }
	int                         getId() const { return id; }
	void                        setId(int i) { id = i; }
	void                        pyHandleCustomCtorArgs(boost::python::tuple& args, boost::python::dict& kw) override;
	static void                 registerChecked(boost::python::object& cls);      // attributes that name themselves in a type error
	void                        updateAttrsChecked(const boost::python::dict& d); // types checked before any is set
	static boost::python::tuple adhesionModes();
	// Makes a change (set(MesoMat&)) after trying it on a copy: a refused value throws and leaves
	// this material as it was, so no attribute needs an old value kept beside it.
	template <class F> void change(F&& set)
	{
		MesoMat trial(*this);
		set(trial);
		trial.postLoad(trial);
		set(*this);
		postLoad(*this);
	}
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(MesoMat,FrictMat,"Material of the adhesive, visco-elasto-plastic meso-particle contact model [Singh2014]_ after [Luding2008]_: hysteretic normal force with loading stiffness $k_1$, un-/re-loading stiffness $k_2(\\delta_{max})$ interpolated up to the limit stiffness $k_p$, tensile branch $-k_c\\delta$, non-contact adhesion ($f_a$, $k_{ca}$), linear viscous damping $\\gamma_0$ and, optionally, the quadratic dashpot $\\gamma_2$ (saved after the other attributes, although YADE lists it as noSave). Use with :yref:`Ip2_MesoMat_MesoMat_MesoPhys` and :yref:`Law2_ScGeom_MesoPhys_Meso`.\n\nEvery assignment is checked; an invalid value raises ``ValueError`` naming the parameter and is not kept. Parameters that constrain each other ($k_p\\geq k_1$; $k_{ca}>0$ when $f_a>0$) are best given together in the constructor, which checks them after applying all keywords. ``young`` is not used by the law (YADE's :yref:`PWaveTimeStep` reads it, but it sees none of the law's stiffnesses: use ``mesocontact.scene.time_step()``).",
		MESO_NORMAL_PARAMS(MESO_MAT_ATTR)
		MESO_ADDED_PARAMS(MESO_MAT_ADDED_ATTR)
		((std::string,adhesion,"none",Attr::triggerPostLoad,"Non-contact adhesion, one of " MESO_ADHESION_MODES(MESO_ADHESION_DOC) "``adhesionModes()`` lists them."))
		((std::string,k2Interpolation,"linear",Attr::triggerPostLoad,"Interpolation of $k_2(\\delta_{max})$ between $k_1$ and $k_p$: 'linear' (Eq. 9) or 'sqrt' (Eq. D.1)."))
		MESO_TANGENTIAL_PARAMS(MESO_MAT_ATTR)
		((bool,dominant,false,Attr::triggerPostLoad,"A dominant material imposes its own parameters, unmixed, on contacts with non-dominant materials (two dominant materials mix as usual). For walls whose law is prescribed, e.g. the strongly adhesive loading walls of [Luding2008]_ ($k_c^{wall}/k_p=20$, $\\mu^{wall}=10$), which the harmonic mean would cap at twice the particles' values.")),
		createIndex(); valid = parse();,
		.add_property("frictionAngle",&MesoMat::getFrictionAngle,&MesoMat::setFrictionAngle,"Sliding friction angle [rad], $\\mu_s=\\tan$ of it, in $[0,\\pi/2)$ (checked on assignment).")
		.add_property("density",&MesoMat::getDensity,&MesoMat::setDensity,"Density of the material [kg/m³], finite and > 0 (checked on assignment).")
		.add_property("young",&MesoMat::getYoung,&MesoMat::setYoung,"Elastic modulus [Pa], finite and > 0 (checked on assignment); not used by the law. :yref:`PWaveTimeStep` reads it but sees none of the law's stiffnesses: set O.dt with ``mesocontact.scene.time_step()``.")
		.def("updateAttrs",&MesoMat::updateAttrsChecked,(boost::python::arg("attrs")),"Sets several attributes at once: an unknown name (AttributeError), a wrong type (TypeError) or an invalid value (ValueError) names the attribute and leaves every attribute as it was.")
		.def("adhesionModes",&MesoMat::adhesionModes,"The names ``adhesion`` takes, in the order of their saved values.").staticmethod("adhesionModes");
		MesoMat::registerChecked(_classObj);
		pychecks::refuseUnknown(_classObj)
	);
	// clang-format on
	REGISTER_CLASS_INDEX(MesoMat, FrictMat);
};
REGISTER_SERIALIZABLE(MesoMat);

// MesoMat's saved layout: YADE's attributes (the added parameters are noSave there), then the added
// parameters, each from its MESO_SINCE_MAT version on; an older file leaves it at its default.
// Found by ADL in place of boost's generic serialize; the material is checked again once they are read.
template <class Ar> void serialize(Ar& ar, MesoMat& m, const unsigned int version)
{
	boost::serialization::access::serialize(ar, m, version);
#define MESO_SERIALIZE_ADDED(name, ...)                                                                                                                        \
	if (version >= MESO_SINCE_MAT_##name) ar& boost::serialization::make_nvp(#name, m.name);
	MESO_ADDED_PARAMS(MESO_SERIALIZE_ADDED)
#undef MESO_SERIALIZE_ADDED
	if (Ar::is_loading::value) m.postLoad(m);
}

// The parameters of one material pair, shared by all its contacts (Ip2_MesoMat_MesoMat_MesoPhys
// makes one per pair of materials and geometry kind); saved once per file, shared again on load.
class MesoPairParams : public Serializable {
public:
	virtual ~MesoPairParams() = default;
	void postLoad(MesoPairParams&); // a saved pair checked (meso::validatePair)
	                                // clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(MesoPairParams,Serializable,"Mixed parameters of one pair of :yref:`MesoMat`, shared by all :yref:`MesoPhys` of that pair (read them through :yref:`MesoPhys`). Made alone, the pair of two default MesoMat.",
		((meso::PairParams,params,,Attr::hidden,"The mixed parameters.")),
		/* a valid pair from the start: YADE's own self-test saves and reloads every class made by default */
		params = meso::mixPair(meso::MaterialParams(), meso::MaterialParams());,
		/*py*/; pychecks::guard(_classObj)
	);
	                                // clang-format on
};
REGISTER_SERIALIZABLE(MesoPairParams);

// The pair's value of a number of MesoParamTable.hpp as a read-only MesoPhys property.
#define MESO_PHYS_PROPERTY(name, def, unit, ok, rule, mix, dest, doc)                                                                                          \
	.add_property(                                                                                                                                         \
	        #name, +[](const MesoPhys& c) -> Real { return c.pair().dest; }, "The pair's :yref:`" #name "<MesoMat." #name ">` (after mixing) [" unit "].")

// Field order matters: a bulk step streams through every contact, and the fields the normal law
// touches each step (history, force parts, last overlap, the pair's pointer, invDeltaMaxP) lie
// together after FrictPhys, so that they span fewer cache lines (callgrind's cache simulation).
class MesoPhys : public FrictPhys {
public:
	virtual ~MesoPhys() = default;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(MesoPhys,FrictPhys,"Physics of one meso-particle contact, created by :yref:`Ip2_MesoMat_MesoMat_MesoPhys`: the mixed pair parameters, the contact history and the energy bookkeeping of :yref:`Law2_ScGeom_MesoPhys_Meso`. All are read-only from Python and are saved with the simulation. ``kn`` is the stiffest branch $k_p$ (for YADE's time-step tools). Contacts of pairs with sliding, rolling or torsion are :yref:`MesoTangentialPhys`, which adds the springs; a plain MesoPhys reports them as zero.",
		((meso::NormalHistory,history,,Attr::hidden,"Contact history (see the read-only properties)."))
		((Real,fHysteretic,0,Attr::hidden,"Hysteretic part of the normal force at the last step [N] (see hystereticForce)."))
		((Real,fViscous,0,Attr::hidden,"Viscous part of the normal force at the last step [N] (see viscousForce); the adhesive part is a function of the overlap and the history, recomputed."))
		((Real,lastDelta,NaN,Attr::hidden,"Overlap at the last step (NaN before the first) [m], for the energy bookkeeping and the lever arm."))
		((shared_ptr<MesoPairParams>,pairParams,,Attr::hidden,"Mixed parameters of the material pair, shared by its contacts (see the read-only properties)."))
		((meso::PairGeometry,geometry,,Attr::hidden,"Limit overlap and radii of this contact (see the read-only properties).")),
		createIndex();,
		.add_property("deltaMax",&MesoPhys::getDeltaMax,"Largest overlap $\\delta_{max}$ of the current mechanical contact, after resets along the $-k_c$ branch [m].")
		.add_property("delta0",&MesoPhys::getDelta0,"Force-free overlap $\\delta_0$ of the current un-/re-loading line [m].")
		.add_property("k2",&MesoPhys::getK2,"Current un-/re-loading stiffness $k_2(\\delta_{max})$ [N/m].")
		.add_property("deltaMaxP",&MesoPhys::getDeltaMaxP,"Limit overlap $\\delta_{max}^p$ (Eq. 10) [m]; inf when $k_p=k_1$.")
		.add_property("delta0P",&MesoPhys::getDelta0P,"Plastic overlap $\\phi_f a_{12}$ on the limit branch (Eq. 11) [m].")
		.add_property("deltaA",&MesoPhys::getDeltaA,"Range of the non-contact force $-f_a/k_{ca}$ (0 without adhesion) [m].")
		.add_property("meshFacet",&MesoPhys::getMeshFacet,"A contact with a mesh of facets: the facet it lies on now, which may be another than the facet of the interaction that holds it (the contact travels across the mesh's edges with its history); -1 for the holder's own facet and for other contacts.")
		.add_property("a12",&MesoPhys::getA12,"Reduced radius $2a_1a_2/(a_1+a_2)$ ($2a$ against a wall) [m].")
		.add_property("branch",&MesoPhys::getBranch,"Branch of the law the contact was on at the last step: 'loading' ($k_1$), 'limit' (the limit branch $k_p$ beyond $\\delta_{max}^p$), 'unloading' (an un-/re-loading line $k_2$), 'tensile' (the tensile limit $-k_c\\delta$), 'nonContact' (no overlap, the non-contact adhesion acting), 'apart' (no overlap, no force) or 'new' (no step yet). Read back from the stored state: it costs the law nothing.")
		.add_property("branchIndex",&MesoPhys::getBranchIndex,"``branch`` as a number for VTK and numpy: 0 new, 1 apart, 2 nonContact, 3 loading, 4 limit, 5 unloading, 6 tensile.")
		.def("branchNames",&MesoPhys::branchNames,"The names ``branch`` takes, in the order of ``branchIndex``.").staticmethod("branchNames")
		.def("dict",&MesoPhys::stateDict,"The attributes YADE's ``dict()`` lists (those of FrictPhys) and the meso contact's state and pair parameters: overlap history, k2, branch, the force parts, the springs.")
		.add_property("touched",&MesoPhys::getTouched,"For 'jumpIn' adhesion: whether the pair has been in mechanical contact (it starts the adhesive force). Kept only for that mode: False for 'none' and 'reversible'.")
		MESO_ALL_PARAMS(MESO_PHYS_PROPERTY)
		.add_property("adhesion",&MesoPhys::getAdhesion,"Adhesion mode of the pair.")
		.add_property("k2Interpolation",&MesoPhys::getK2Interpolation,"Interpolation of $k_2$ for the pair.")
		.add_property("hystereticForce",&MesoPhys::getFh,"Hysteretic contact part of the normal force at the last step (> 0 repulsive) [N]. The total is ``normalForce``.")
		.add_property("adhesiveForce",&MesoPhys::getFadh,"Non-contact adhesive part of the normal force at the last step [N].")
		.add_property("viscousForce",&MesoPhys::getFv,"Viscous part of the normal force at the last step [N].")
		.add_property("coulombLevel",&MesoPhys::getCoulombLevel,"What the Coulomb limits of sliding, rolling and torsion scale with at the last step: $f_h+f_v+k_c\\delta$, the contact part of the normal force (hysteretic plus viscous) measured from the adhesive branch (0 before the first step) [N]. The law clamps it at 0.")
		.add_property("slidingSpring",&MesoPhys::getXiT,"Sliding spring $\\xi_t$ in the tangent plane [m]; the force on body 1 is ``-shearForce``.")
		.add_property("rollingSpring",&MesoPhys::getXiR,"Rolling spring $\\xi_r$ [m].")
		.add_property("torsionSpring",&MesoPhys::getXiO,"Torsion spring $\\xi_o$ along the normal [m].")
		.add_property("rollingForce",&MesoPhys::getFR,"Rolling quasi-force $f_r$ [N]: torque $-a'_{12}\\,n\\times f_r$ on body 1, opposite on body 2.")
		.add_property("torsionForce",&MesoPhys::getFO,"Torsion quasi-force $f_o$ [N]: torque $a'_{12} f_o n$ on body 1, opposite on body 2.")
		.add_property("rollingTorque",&MesoPhys::getRollingTorque,"Rolling resistance torque on body 1 at the last step [N m].")
		.add_property("torsionTorque",&MesoPhys::getTorsionTorque,"Torsion resistance torque on body 1 at the last step [N m].")
		.add_property("leverArm",&MesoPhys::getLeverArm,"Lever arm $a'_{12}$ of rolling and torsion at the last step [m].")
		.add_property("muS",&MesoPhys::getMuS,"Static sliding coefficient of the pair [-].")
		.add_property("byteSize",&MesoPhys::byteSize,"Memory of this object [bytes] (what each contact costs; a MesoTangentialPhys is larger).")
		.add_property("frictPhysByteSize",&MesoPhys::frictPhysByteSize,"Memory of one FrictPhys object [bytes], for comparison.");
		pychecks::guard(_classObj)
	);
	// clang-format on
	// The pair's parameters; defaults for a MesoPhys not made by the Ip2 (so that reading it cannot crash).
	const meso::PairParams& pair() const
	{
		static const meso::PairParams none;
		return pairParams ? pairParams->params : none;
	}
	Real        getDeltaMax() const { return history.deltaMax; }
	Real        getDelta0() const { return history.delta0; }
	Real        getK2() const { return meso::unloadingStiffness(pair(), geometry, history); }
	bool        getTouched() const { return history.touched; }
	Real        getDeltaMaxP() const { return geometry.deltaMaxP(); }
	Real        getDelta0P() const { return geometry.delta0P(pair()); }
	Real        getDeltaA() const { return pair().deltaA; }
	Real        getA12() const { return geometry.a12(); }
	int         getMeshFacet() const { return geometry.meshFacet; }
	std::string getAdhesion() const { return meso::adhesionName(pair().adhesion); }
	std::string getK2Interpolation() const { return meso::k2InterpolationName(pair().k2Interpolation); }
	Real        getFh() const { return fHysteretic; }
	Real        getFadh() const { return std::isnan(lastDelta) ? 0.0 : meso::adhesiveForceAfter(pair(), history, lastDelta); }
	Real        getFv() const { return fViscous; }
	Real        getCoulombLevel() const { return std::isnan(lastDelta) ? 0.0 : meso::coulombLevel(pair(), fHysteretic, fViscous, lastDelta); }
	// The springs of a MesoTangentialPhys; zero for a contact without tangential mechanisms.
	const meso::TangentialState& tangentialState() const;
	Vector3r                     getXiT() const { return tangentialState().xiT; }
	Vector3r                     getXiR() const { return tangentialState().xiR; }
	Real                         getXiO() const { return tangentialState().xiO; }
	Vector3r                     getFR() const { return tangentialState().fR; }
	Real                         getFO() const { return tangentialState().fO; }
	Vector3r                     getRollingTorque() const { return -getLeverArm() * tangentialState().nPrev.cross(tangentialState().fR); }
	Vector3r                     getTorsionTorque() const { return getLeverArm() * tangentialState().fO * tangentialState().nPrev; }
	// The lever arm is a function of the overlap: recomputed here, not stored per contact.
	Real         getLeverArm() const { return pair().tangential && !std::isnan(lastDelta) ? meso::contactArms(pair(), geometry, lastDelta).lever : 0; }
	Real         getMuS() const { return pair().sliding.muS; }
	meso::Branch branch() const { return pairParams ? meso::branchAfter(pair(), geometry, history, lastDelta, fHysteretic) : meso::Branch::New; }
	std::string  getBranch() const { return meso::branchName(branch()); }
	static boost::python::tuple branchNames();
	int                         getBranchIndex() const { return static_cast<int>(branch()); }
	boost::python::dict         stateDict() const;
	int                         byteSize() const; // of this object's class
	int                         frictPhysByteSize() const { return sizeof(FrictPhys); }
	// A loaded contact whose class does not fit its pair's mechanisms would be read as the wrong type.
	void postLoad(MesoPhys&);
	// The interaction whose law step last used this phys (not saved): a phys met on another
	// interaction was loaded, restored or assigned from Python, and is checked once there.
	const Interaction* owner = nullptr;
	REGISTER_CLASS_INDEX(MesoPhys, FrictPhys);
};
REGISTER_SERIALIZABLE(MesoPhys);

// A contact whose pair has sliding, rolling or torsion: a MesoPhys with the springs. Contacts
// without them stay MesoPhys and do not carry the springs (a contact's size is what bulk runs pay).
class MesoTangentialPhys : public MesoPhys {
public:
	virtual ~MesoTangentialPhys() = default;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR(MesoTangentialPhys,MesoPhys,"A :yref:`MesoPhys` with the sliding, rolling and torsion springs of [Luding2008]_, created by :yref:`Ip2_MesoMat_MesoMat_MesoPhys` for pairs that have any of them (read them through the properties of :yref:`MesoPhys`).",
		((meso::TangentialState,tangential,,Attr::hidden,"Springs and quasi-forces of rolling and torsion (see the read-only properties); the sliding force is ``-shearForce``.")),
		createIndex();
	);
	// clang-format on
	REGISTER_CLASS_INDEX(MesoTangentialPhys, MesoPhys);
};
REGISTER_SERIALIZABLE(MesoTangentialPhys);

class Ip2_MesoMat_MesoMat_MesoPhys : public IPhysFunctor {
	friend class MesoContactStore; // checks restored contacts against mix() of their bodies' materials
	// One MesoPairParams per (material, material, ScGeom6D or not), made on first use; the Ip2 runs
	// inside YADE's OpenMP loop, hence the mutex (taken once per new contact, not per step).
	struct Shared {
		shared_ptr<Material>       m1, m2; // held, so that the addresses in the key stay theirs
		unsigned long              revision1 = 0, revision2 = 0;
		shared_ptr<MesoPairParams> params;
	};
	std::map<std::tuple<const Material*, const Material*, bool>, Shared> sharedParams;
	std::mutex                                                           sharedMutex;
	shared_ptr<MesoPairParams> pairParams(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, bool geom6D);
	meso::PairParams           mix(const MesoMat& m1, const MesoMat& m2, bool rotations) const; // the one mixing, for contacts and Python
	std::atomic<bool>          dtWarned { false }, rangeWarned { false }, depthWarned { false };
	void                       checkTimeStep(const MesoPhys& phys, const Interaction& I);  // updates stableDt, warns once
	void                       checkDetection(const MesoPhys& phys, const Interaction& I); // reversible adhesion: warns once if made in contact
	void                       checkDepth(const Interaction& I);                           // warns once for a contact made deeper than a radius

public:
	void go(const shared_ptr<Material>& m1, const shared_ptr<Material>& m2, const shared_ptr<Interaction>& I) override;
	void postLoad(Ip2_MesoMat_MesoMat_MesoPhys&);
	void pyHandleCustomCtorArgs(boost::python::tuple& args, boost::python::dict& kw) override;
	// Gives a live contact its bodies' present materials, keeping its history; throws
	// std::invalid_argument if that would change the hysteretic normal law or the contact class.
	void adoptMaterials(const boost::python::object& interaction);
	// The pair parameters the contacts of two materials get: the one mixing rule, for Python too.
	// Python entry points: every argument is an object checked by name (Boost's converters name none).
	boost::python::dict mixedParameters(const boost::python::object& m1, const boost::python::object& m2, const boost::python::object& rotations) const;
	Real                stableStepFor(
	                       const boost::python::object& m1,
	                       const boost::python::object& m2,
	                       const boost::python::object& radius1,
	                       const boost::python::object& radius2,
	                       const boost::python::object& rotations) const;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Ip2_MesoMat_MesoMat_MesoPhys,IPhysFunctor,"Creates :yref:`MesoPhys` from two :yref:`MesoMat`. Unlike materials mix as follows: $k_1$, $k_p$, $k_c$, $f_a$, $k_{ca}$, $\\gamma_0$ and the tangential springs and dashpots by the harmonic mean $2xy/(x+y)$ (so a pair of equal materials has their values, and a material without a mechanism switches it off); $\\phi_f$ by the arithmetic mean; the friction coefficients $\\mu_s$, $\\mu_r$, $\\mu_o$ and $\\phi_d$ by the smaller one (as :yref:`Ip2_FrictMat_FrictMat_FrictPhys`); the adhesion mode is the weaker of the two ('none' < 'jumpIn' < 'reversible'); 'sqrt' interpolation only when both ask for it.\n\n$a_{12}=2a_1a_2/(a_1+a_2)$ from the radii of the two spheres; against a wall, box or facet $a_{12}=2a$ of the sphere. Rolling and torsion act when the geometry is :yref:`ScGeom6D`.",
		((std::string,leverArm,"reduced",Attr::triggerPostLoad,"Lever arm $a'_{12}$ of rolling and torsion (open in [Luding2008]_): 'reduced' = $a'_1a'_2/(a'_1+a'_2)$ with $a'=a-\\delta/2$ ($a'$ of the sphere against a wall), or 'a12' = twice that. The factor 2 scales the torques of given $k_r$, $k_o$ by 4 and the limit torques by 2."))
		((int,leverFactor,1,(Attr::hidden|Attr::noSave),"1 or 2, from leverArm"))
		((Real,stableDt,std::numeric_limits<Real>::infinity(),(Attr::readonly|Attr::noSave),"Smallest stable time step of the contacts this functor has made [s]: per contact the leapfrog bound $(2/\\omega)(\\sqrt{1+\\zeta^2}-\\zeta)$ of its stiffest element (normal $k_p$ with $\\gamma_0$ on the reduced mass; sliding, rolling and torsion with the spins' inertia). When O.dt exceeds it at a new contact, a warning names the contact, once per functor.")),
		/*ctor*/,
		.def("stableStep",&Ip2_MesoMat_MesoMat_MesoPhys::stableStepFor,(boost::python::arg("material1"),boost::python::arg("material2"),boost::python::arg("radius1"),boost::python::arg("radius2")=0,boost::python::arg("rotations")=true),"The stable time step [s] of a contact between a free sphere of ``material1`` and radius ``radius1`` and a free sphere of ``material2`` and ``radius2`` (0: a fixed wall, box or facet), masses and inertia from the materials' densities: the bound :yref:`stableDt<Ip2_MesoMat_MesoMat_MesoPhys.stableDt>` applies to each contact, from the same code, before any contact exists. ``mesocontact.scene.time_step`` takes its minimum over a scene.")
		.def("mixedParameters",&Ip2_MesoMat_MesoMat_MesoPhys::mixedParameters,(boost::python::arg("material1"),boost::python::arg("material2"),boost::python::arg("rotations")=true),"The parameters the contacts between two :yref:`MesoMat` get (the mixing rules above, ``dominant`` included; ``rotations``: whether the geometry is :yref:`ScGeom6D`), as a dict: 'k1', 'kp', 'kc', 'phiF', 'fa', 'kca', 'gammaN', 'gammaN2', 'phiD', 'deltaA' (range $-f_a/k_{ca}$ of the non-contact force, $\\leq 0$), 'adhesion', 'k2Interpolation', 'leverFactor', and 'sliding', 'rolling', 'torsion' (dicts of 'k', 'gamma', 'muS', 'muD', 'acts'). The same code as the contacts use: scripts need not repeat the rules.")
		.def("adoptMaterials",&Ip2_MesoMat_MesoMat_MesoPhys::adoptMaterials,(boost::python::arg("interaction")),"Gives a live contact (a real interaction with :yref:`MesoPhys`) the parameters of its bodies' present materials while keeping its history ($\\delta_{max}$, $\\delta_0$, springs): for a material changed during a run, e.g. loading walls made adhesive for a test after the sample was prepared against smooth walls (a contact remade by setting ``phys = None`` would start afresh). The hysteretic normal law ($k_1$, $k_p$, $\\phi_f$, $k_2$ interpolation) and the tangential mechanisms must stay as they are, so that the force stays continuous; otherwise ``ValueError`` names what differs.");
		pychecks::checked(_classObj, "leverArm", &Ip2_MesoMat_MesoMat_MesoPhys::leverArm);
		pychecks::guard(_classObj)
	);
	// clang-format on
	FUNCTOR2D(MesoMat, MesoMat);
};
REGISTER_SERIALIZABLE(Ip2_MesoMat_MesoMat_MesoPhys);

struct MesoKinematics; // of one contact's tangential elements (MesoLaw2.cpp)

class Law2_ScGeom_MesoPhys_Meso : public LawFunctor {
	// YADE's EnergyTracker looks a new name up without a lock: threads that meet it first at the same
	// time each register it, and the shares added under all but one index are lost. So the law
	// registers its names once, under its own lock, before any thread adds to them.
	std::mutex        energyMutex;
	std::atomic<bool> normalEnergiesReady { false }, tangentialEnergiesReady { false };
	void              registerEnergies(bool tangential);
	void              addEnergies(const meso::NormalEnergyStep& e);
	void              addEnergies(const meso::TangentialEnergy& e);
	std::atomic<bool> foreignWarned { false };
	bool              dropForeign(shared_ptr<IPhys>& ip, const Interaction* I); // a MesoPhys not made by the Ip2
	std::atomic<bool> borrowedWarned { false };
	bool              adopt(shared_ptr<IPhys>& ip, Interaction* I); // a phys met on this interaction for the first time
	// The steps of go(), in MesoLaw2.cpp: the normal force (with its energy when tracked), then
	// sliding, rolling and torsion from the contact's kinematics.
	meso::NormalForce normalStep(MesoPhys& phys, const meso::PairParams& p, Real delta, Real vn);
	void
	tangentialStep(MesoTangentialPhys& phys, const meso::PairParams& p, const MesoKinematics& k, const Vector3r& n, Real delta, Real level, Vector3r& fT);

public:
	// Set by a MesoBackgroundDamping right after this law's InteractionLoop: the law adds each contact's
	// neighbour motion there, so that the drag needs no pass of its own (null: nothing to add).
	shared_ptr<MesoNeighbourSums> neighbourSums;
	bool                          go(shared_ptr<IGeom>& ig, shared_ptr<IPhys>& ip, Interaction* I) override;
	void                          pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw) override { pychecks::ctorKeywords(*this, kw); }
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(Law2_ScGeom_MesoPhys_Meso,LawFunctor,"The normal force of the meso-particle contact model [Singh2014]_: hysteretic contact force (plastic loading $k_1\\delta$, un-/re-loading $k_2(\\delta-\\delta_0)$, limit branch $k_p(\\delta-\\phi_f a_{12})$, tensile limit $-k_c\\delta$ with the exact history update), plus the non-contact adhesion of :yref:`MesoMat.adhesion` and the viscous force $(\\gamma_0+\\gamma_2|v_n|)v_n$ in contact. The interaction is kept while the non-contact force can act ($\\delta>-f_a/k_{ca}$) and erased beyond; the collider and :yref:`Ig2_Sphere_Sphere_ScGeom.interactionDetectionFactor` must detect pairs at that gap (``mesocontact.pair`` sets them).\n\nWith :yref:`O.trackEnergy<Omega.trackEnergy>`, ``O.energy`` holds 'mesoElastic' (stored elastic energy, consistent with the leapfrog kinetic energy), 'mesoPlastic' (hysteretic dissipation), 'mesoAdhesive' (work absorbed by the adhesive force; negative while it binds) and 'mesoViscous' (viscous dissipation); with tangential mechanisms also 'mesoSprings' (energy stored in the sliding, rolling and torsion springs) and 'mesoSliding', 'mesoRolling', 'mesoTorsion' (their dissipation, slip and dashpot, including what a spring holds when the contact opens) [J].\n\nSliding, rolling and torsion follow [Luding2008]_: one spring-dashpot-Coulomb element each, the spring advanced by the relative velocity first, trial force $-k\\xi-\\gamma v$, static limit $\\mu_s(f_n+k_c\\delta)$ to start sliding and dynamic limit $\\mu_d(f_n+k_c\\delta)$ for the force while sliding and to go on sliding with $f_n$ the contact part of the normal force (hysteretic plus viscous, without the non-contact $f_a$ term) measured from the adhesive branch, spring reset to $-(f+\\gamma v)/k$ on slip, springs rotated with the contact. Sliding acts at the contact point (force and torques); rolling and torsion only as torques.",
		((int,elasticIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoElastic' in O.energy"))
		((int,plasticIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoPlastic' in O.energy"))
		((int,adhesiveIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoAdhesive' in O.energy"))
		((int,viscousIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoViscous' in O.energy"))
		((int,springsIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoSprings' in O.energy"))
		((int,slidingIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoSliding' in O.energy"))
		((int,rollingIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoRolling' in O.energy"))
		((int,torsionIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoTorsion' in O.energy")),
		/*ctor*/,
		/*py*/; pychecks::guard(_classObj)
	);
	// clang-format on
	FUNCTOR2D(ScGeom, MesoPhys);
};
REGISTER_SERIALIZABLE(Law2_ScGeom_MesoPhys_Meso);

} // namespace yade

// boost::serialization of the core structs (they live in MesoPhys as hidden attributes).
namespace boost {
namespace serialization {
	// Version 1 added phiD (version 0 files: recovered from the elements, which hold it as muD/muS);
	// the added parameters from their MESO_SINCE_PAIR versions (older files: their defaults, which
	// leave the law as it was).
	// The tags of the flags and of the torsion element are those of the first files.
	template <class Ar> void serialize(Ar& ar, meso::PairParams& p, const unsigned int version)
	{
		int adhesion = static_cast<int>(p.adhesion), interp = static_cast<int>(p.k2Interpolation);
#define MESO_SERIALIZE(name, ...) ar& make_nvp(#name, p.name);
		MESO_NORMAL_PARAMS(MESO_SERIALIZE)
#undef MESO_SERIALIZE
		ar& make_nvp("adhesion", adhesion) & make_nvp("k2Interpolation", interp);
		ar& make_nvp("deltaA", p.deltaA) & make_nvp("delta0PerMaxP", p.delta0PerMaxP);
		ar& make_nvp("sliding", p.sliding) & make_nvp("rolling", p.rolling) & make_nvp("twisting", p.torsion);
		ar& make_nvp("leverFactor", p.leverFactor) & make_nvp("rollTwist", p.rollingOrTorsion) & make_nvp("tangential", p.tangential);
		ar& make_nvp("slides", p.slidingActs) & make_nvp("rolls", p.rollingActs) & make_nvp("twists", p.torsionActs);
		if (version >= 1) ar& make_nvp("phiD", p.phiD);
		else {
			p.phiD = 1;
			for (const meso::ElementParams* e : { &p.sliding, &p.rolling, &p.torsion })
				if (e->muS > 0) {
					p.phiD = e->muD / e->muS;
					break;
				}
		}
#define MESO_SERIALIZE(name, def, unit, ok, rule, mix, dest, doc)                                                                                              \
	if (version >= MESO_SINCE_PAIR_##name) ar& make_nvp(#name, p.dest);                                                                                    \
	else                                                                                                                                                   \
		p.dest = def;
		MESO_ADDED_PARAMS(MESO_SERIALIZE)
#undef MESO_SERIALIZE
		p.adhesion        = static_cast<meso::Adhesion>(adhesion);
		p.k2Interpolation = static_cast<meso::K2Interpolation>(interp);
	}
	// Version 1 added meshFacet (version 0 files: -1, the contact on the facet that made it).
	template <class Ar> void serialize(Ar& ar, meso::PairGeometry& g, const unsigned int version)
	{
		ar& make_nvp("radius1", g.radius1) & make_nvp("radius2", g.radius2) & make_nvp("invDeltaMaxP", g.invDeltaMaxP);
		if (version >= 1) ar& make_nvp("meshFacet", g.meshFacet);
		else
			g.meshFacet = -1;
	}
	template <class Ar> void serialize(Ar& ar, meso::NormalHistory& h, const unsigned int)
	{
		ar& make_nvp("deltaMax", h.deltaMax) & make_nvp("delta0", h.delta0) & make_nvp("touched", h.touched);
	}
	template <class Ar> void serialize(Ar& ar, meso::TangentialState& s, const unsigned int)
	{
		ar& make_nvp("xiT", s.xiT) & make_nvp("xiR", s.xiR) & make_nvp("xiO", s.xiO);
		ar& make_nvp("fR", s.fR) & make_nvp("fO", s.fO) & make_nvp("nPrev", s.nPrev);
		ar& make_nvp("slidingT", s.slidingT) & make_nvp("slidingR", s.slidingR) & make_nvp("slidingO", s.slidingO);
	}
	template <class Ar> void serialize(Ar& ar, meso::ElementParams& e, const unsigned int)
	{
		ar& make_nvp("k", e.k) & make_nvp("gamma", e.gamma) & make_nvp("muS", e.muS) & make_nvp("muD", e.muD);
	}
}
} // namespace boost::serialization
BOOST_CLASS_VERSION(meso::PairParams, 2)
BOOST_CLASS_VERSION(meso::PairGeometry, 1)
BOOST_CLASS_VERSION(yade::MesoMat, 1) // 1: the added parameters saved (serialize(MesoMat) above)
