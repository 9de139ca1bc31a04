#include "MesoBackgroundDamping.hpp"
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <pkg/common/Sphere.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoBackgroundDamping));

void MesoBackgroundDamping::action()
{
	if (!(gammaB >= 0) || !(gammaBR >= 0)) throw std::invalid_argument("gammaB and gammaBR of MesoBackgroundDamping must be >= 0");
	const long n     = static_cast<long>(scene->bodies->size());
	const bool track = scene->trackEnergy;
	const Real dt    = scene->dt;
	if (track && static_cast<long>(prevVel.size()) < n) {
		prevVel.resize(n, Vector3r::Zero());
		prevAngVel.resize(n, Vector3r::Zero());
		hasPrev.resize(n, 0);
	}
	Real dissipated = 0;
#ifdef YADE_OPENMP
#pragma omp parallel for reduction(+ : dissipated) schedule(static)
#endif
	for (long id = 0; id < n; ++id) {
		const shared_ptr<Body>& b = (*scene->bodies)[id];
		if (!b || !b->isDynamic() || b->isClumpMember()) continue;
		const State&   st     = *b->state;
		const auto*    sphere = dynamic_cast<const Sphere*>(b->shape.get());
		const Real     rot    = sphere ? gammaBR * sphere->radius * sphere->radius : 0;
		if (track) {
			// The drag applied last step acted while the velocity went from prevVel to vel: its work,
			// in the leapfrog's own measure, is F . (v_prev + v) dt / 2 (exact for translation).
			if (hasPrev[id]) {
				dissipated += gammaB * prevVel[id].dot(prevVel[id] + st.vel) * 0.5 * dt;
				dissipated += rot * prevAngVel[id].dot(prevAngVel[id] + st.angVel) * 0.5 * dt;
			}
			prevVel[id]    = st.vel;
			prevAngVel[id] = st.angVel;
			hasPrev[id]    = 1;
		}
		scene->forces.addForce(id, -gammaB * st.vel);
		if (rot > 0) scene->forces.addTorque(id, -rot * st.angVel);
	}
	if (track) scene->energy->add(dissipated, "mesoBackground", energyIx, false);
}

} // namespace yade
