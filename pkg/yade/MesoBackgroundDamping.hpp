// Viscous background damping of Luding 2008: a drag on every particle, force -gammaB (v - v_ref)
// and torque -gammaBR a^2 (w - w_ref), applied as an engine before NewtonIntegrator. The
// reference is the lab frame (at rest) or the rigid motion of the particle's contact neighbours,
// so that a cluster moving as a body, or the imposed homogeneous deformation, is not dragged.
#pragma once
#include "PyChecks.hpp"
#include "MesoNeighbourSums.hpp"
#include <core/GlobalEngine.hpp>
#include <vector>

namespace yade {

class Law2_ScGeom_MesoPhys_Meso;

class MesoBackgroundDamping : public GlobalEngine {
	using Neighbours = MesoNeighbourSums::Sums;
	std::vector<Neighbours> neighbours; // per body, this step
	std::vector<char>       isSphere;
	// sums: filled by the laws of the InteractionLoop right before this engine; sumLaws: the laws it was
	// handed to, so that one no longer there stops adding.
	using Laws                         = std::vector<shared_ptr<Law2_ScGeom_MesoPhys_Meso>>;
	shared_ptr<MesoNeighbourSums> sums = shared_ptr<MesoNeighbourSums>(new MesoNeighbourSums());
	Laws                          sumLaws;
	void                          validate() const; // throws std::invalid_argument naming the attribute and value
	void                          sumNeighbours();  // the engine's own pass over the interactions
	Laws                          precedingLaws() const;
	bool                          takeLawSums(const Laws& laws);                  // the laws' sums of this step, if complete
	void                          prepareLawSums(const Laws& laws, long nBodies); // for the next step
	Real                          validGammaB = 0, validGammaBR = 0;              // the attributes as last validated (constructor, postLoad)
	std::string                   validReference;

public:
	void        action() override;
	void        postLoad(MesoBackgroundDamping&); // validates an assignment; a refused one is undone
	void        pyHandleCustomCtorArgs(boost::python::tuple& args, boost::python::dict& kw) override;
	static void registerChecked(boost::python::object& cls);
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS_CTOR_PY(MesoBackgroundDamping,GlobalEngine,"Viscous background damping of [Luding2008]_: every dynamic body gets the force $-\\gamma_b\\,(v-v_{ref})$ and, if it is a sphere of radius $a$, the torque $-\\gamma_{br}\\,a^2(\\omega-\\omega_{ref})$ (the form with the right units; the paper leaves it open). Not YADE's non-viscous :yref:`NewtonIntegrator.damping`. Put it after :yref:`InteractionLoop` and before :yref:`NewtonIntegrator`.\n\nWith ``reference='lab'`` the reference is rest ($v_{ref}=\\omega_{ref}=0$): a drag against the surrounding medium, which also slows a free gas (useful while preparing a packing). With ``reference='contacts'`` it is the rigid motion of the body's mechanical contact neighbours (overlap > 0): $\\omega_{ref}=\\bar\\omega$, $v_{ref}=\\bar v+\\bar\\omega\\times(x-\\bar x)$, the bars averaging the neighbours' spins, positions and velocities (for a non-spherical neighbour such as a wall, its contact point and that point's velocity). A cluster translating and rotating as a rigid body, or a layer moving with a wall, feels no drag; a body rattling among resting neighbours feels $-\\gamma_b v$; a body without contacts feels none.\n\nWith :yref:`O.trackEnergy<Omega.trackEnergy>` the work of the drag is 'mesoBackground' in ``O.energy``, booked consistently with the leapfrog kinetic energy.",
		((Real,gammaB,0,Attr::triggerPostLoad,"Translational drag coefficient $\\gamma_b\\geq 0$ [kg/s], finite (checked on assignment)."))
		((Real,gammaBR,0,Attr::triggerPostLoad,"Rotational drag coefficient $\\gamma_{br}\\geq 0$ [kg/s], finite: torque $-\\gamma_{br}a^2(\\omega-\\omega_{ref})$."))
		((std::string,reference,"lab",Attr::triggerPostLoad,"What the drag acts relative to: 'lab' (rest) or 'contacts' (the rigid motion of the body's contact neighbours)."))
		((bool,sumInLaw,true,Attr::noSave,"Not saved (files of earlier versions must still load; after ``O.load`` it is ``True``). With ``reference='contacts'``: let :yref:`Law2_ScGeom_MesoPhys_Meso` add up the neighbours' motion while it visits each contact, when this engine directly follows the :yref:`InteractionLoop` and every law there is that one (otherwise, and on the first step, the engine sums itself, as with ``False``). Both give the same drag (to rounding under OpenMP, bitwise on one thread); ``False`` only costs a second pass over the interactions."))
		((long,lawSumSteps,0,(Attr::readonly|Attr::noSave),"How many steps took the reference from the laws' sums (see ``sumInLaw``); the others summed in the engine."))
		((std::vector<Vector3r>,prevVel,,Attr::hidden,"Velocities when the previous drag was applied (energy tracking; saved, so that the booking goes on after O.load)."))
		((std::vector<Vector3r>,prevAngVel,,Attr::hidden,"Spins when the previous drag was applied."))
		((std::vector<Vector3r>,prevForce,,Attr::hidden,"The previous drag forces."))
		((std::vector<Vector3r>,prevTorque,,Attr::hidden,"The previous drag torques."))
		((std::vector<int>,hasPrev,,Attr::hidden,"Whether a body got a drag at the previous step (1) or not (0)."))
		((int,energyIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoBackground' in O.energy")),
		/*ctor*/ validGammaB = gammaB; validGammaBR = gammaBR; validReference = reference;,
		/*py*/; MesoBackgroundDamping::registerChecked(_classObj); pychecks::guard(_classObj)
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(MesoBackgroundDamping);

} // namespace yade
