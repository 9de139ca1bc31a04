#include "MesoBackgroundDamping.hpp"
#include <core/Interaction.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoBackgroundDamping));

void MesoBackgroundDamping::validate() const
{
	for (const auto& [name, value] : {std::pair<const char*, Real> {"gammaB", gammaB}, {"gammaBR", gammaBR}}) {
		if (!(value >= 0) || !std::isfinite(value)) {
			std::ostringstream msg;
			msg << "MesoBackgroundDamping." << name << " = " << value << " is invalid: must be finite and >= 0";
			throw std::invalid_argument(msg.str());
		}
	}
	if (reference != "lab" && reference != "contacts")
		throw std::invalid_argument("MesoBackgroundDamping.reference = '" + reference + "' is invalid: must be 'lab' or 'contacts'");
}

namespace {
	// The rigid motion of a body's mechanical contact neighbours, evaluated at the body's centre:
	// (v_ref, w_ref). false if it has none (a free body: its own motion is rigid).
	bool neighbourMotion(const Body& b, const BodyContainer& bodies, Vector3r& vRef, Vector3r& wRef)
	{
		Vector3r sumX = Vector3r::Zero(), sumV = Vector3r::Zero(), sumW = Vector3r::Zero();
		int      n    = 0;
		for (const auto& [otherId, I] : b.intrs) {
			if (!I->isReal()) continue;
			const auto* geom = dynamic_cast<const ScGeom*>(I->geom.get());
			if (!geom || !(geom->penetrationDepth > 0)) continue;
			const shared_ptr<Body>& o = bodies[otherId];
			if (!o) continue;
			const State& s = *o->state;
			if (dynamic_cast<const Sphere*>(o->shape.get())) { // its centre
				sumX += s.pos;
				sumV += s.vel;
			} else { // a wall or another large body: the material point at the contact
				sumX += geom->contactPoint;
				sumV += s.vel + s.angVel.cross(geom->contactPoint - s.pos);
			}
			sumW += s.angVel;
			++n;
		}
		if (n == 0) return false;
		const Real inv = Real(1) / n;
		wRef           = sumW * inv;
		vRef           = sumV * inv + wRef.cross(b.state->pos - sumX * inv);
		return true;
	}
}

void MesoBackgroundDamping::action()
{
	validate();
	const bool relative = reference == "contacts";
	const long n        = static_cast<long>(scene->bodies->size());
	const bool track    = scene->trackEnergy;
	const Real dt       = scene->dt;
	if (track && static_cast<long>(prevVel.size()) < n) {
		for (auto* v : {&prevVel, &prevAngVel, &prevForce, &prevTorque})
			v->resize(n, Vector3r::Zero());
		hasPrev.resize(n, 0);
	}
	const BodyContainer& bodies     = *scene->bodies;
	Real                 dissipated = 0;
#ifdef YADE_OPENMP
#pragma omp parallel for reduction(+ : dissipated) schedule(static)
#endif
	for (long id = 0; id < n; ++id) {
		const shared_ptr<Body>& b = bodies[id];
		if (!b || !b->isDynamic() || b->isClumpMember()) continue;
		const State& st     = *b->state;
		const auto*  sphere = dynamic_cast<const Sphere*>(b->shape.get());
		const Real   rot    = sphere ? gammaBR * sphere->radius * sphere->radius : 0;
		if (track && hasPrev[id]) {
			// The drag applied last step acted while the velocity went from prevVel to vel: its work,
			// in the leapfrog's own measure, is F . (v_prev + v) dt / 2 (exact for translation).
			dissipated -= prevForce[id].dot(prevVel[id] + st.vel) * 0.5 * dt;
			dissipated -= prevTorque[id].dot(prevAngVel[id] + st.angVel) * 0.5 * dt;
			hasPrev[id] = 0;
		}
		Vector3r vRef = Vector3r::Zero(), wRef = Vector3r::Zero();
		if (relative && !neighbourMotion(*b, bodies, vRef, wRef)) continue;
		const Vector3r force  = -gammaB * (st.vel - vRef);
		const Vector3r torque = -rot * (st.angVel - wRef);
		if (track) {
			prevVel[id]    = st.vel;
			prevAngVel[id] = st.angVel;
			prevForce[id]  = force;
			prevTorque[id] = torque;
			hasPrev[id]    = 1;
		}
		scene->forces.addForce(id, force);
		if (rot > 0) scene->forces.addTorque(id, torque);
	}
	if (track) scene->energy->add(dissipated, "mesoBackground", energyIx, false);
}

} // namespace yade
