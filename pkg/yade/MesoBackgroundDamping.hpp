// Viscous background damping of Luding 2008: a drag on every particle, force -gammaB v and
// torque -gammaBR a^2 w (a: sphere radius), applied as an engine before NewtonIntegrator.
#pragma once
#include <core/GlobalEngine.hpp>
#include <vector>

namespace yade {

class MesoBackgroundDamping : public GlobalEngine {
	std::vector<Vector3r> prevVel, prevAngVel; // velocities when the previous drag was applied
	std::vector<char>     hasPrev;

public:
	void action() override;
	// clang-format off
	YADE_CLASS_BASE_DOC_ATTRS(MesoBackgroundDamping,GlobalEngine,"Viscous background damping of [Luding2008]_: every dynamic body gets the force $-\\gamma_b\\,v$ and, if it is a sphere of radius $a$, the torque $-\\gamma_{br}\\,a^2\\omega$ (the form with the right units; the paper leaves it open). Not YADE's non-viscous :yref:`NewtonIntegrator.damping`. Put it after :yref:`InteractionLoop` and before :yref:`NewtonIntegrator`. With :yref:`O.trackEnergy<Omega.trackEnergy>` its dissipation is 'mesoBackground' in ``O.energy``, booked consistently with the leapfrog kinetic energy.",
		((Real,gammaB,0,,"Translational drag coefficient $\\gamma_b\\geq 0$ [kg/s]."))
		((Real,gammaBR,0,,"Rotational drag coefficient $\\gamma_{br}\\geq 0$ [kg/s]: torque $-\\gamma_{br}a^2\\omega$."))
		((int,energyIx,-1,(Attr::hidden|Attr::noSave),"Index of 'mesoBackground' in O.energy"))
	);
	// clang-format on
};
REGISTER_SERIALIZABLE(MesoBackgroundDamping);

} // namespace yade
