#include "MesoBackgroundDamping.hpp"
#include "MesoContact.hpp"
#include "PyChecks.hpp"
#include <core/Interaction.hpp>
#include <core/InteractionLoop.hpp>
#include <core/Scene.hpp>
#include <core/State.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((MesoBackgroundDamping));

void MesoBackgroundDamping::validate() const
{
	for (const auto& [name, value] : { std::pair<const char*, Real> { "gammaB", gammaB }, { "gammaBR", gammaBR } }) {
		if (!(value >= 0) || !std::isfinite(value)) {
			std::ostringstream msg;
			msg << "MesoBackgroundDamping." << name << " = " << value << " is invalid: must be finite and >= 0";
			throw std::invalid_argument(msg.str());
		}
	}
	if (reference != "lab" && reference != "contacts")
		throw std::invalid_argument("MesoBackgroundDamping.reference = '" + reference + "' is invalid: must be 'lab' or 'contacts'");
}

void MesoBackgroundDamping::postLoad(MesoBackgroundDamping&)
{
	try {
		validate();
	} catch (const std::invalid_argument&) {
		gammaB    = validGammaB;
		gammaBR   = validGammaBR;
		reference = validReference;
		throw;
	}
	validGammaB    = gammaB;
	validGammaBR   = gammaBR;
	validReference = reference;
}

void MesoBackgroundDamping::pyHandleCustomCtorArgs(boost::python::tuple&, boost::python::dict& kw)
{
	using pychecks::Kind;
	static const pychecks::Field fields[] = { { "gammaB", Kind::Number }, { "gammaBR", Kind::Number }, { "reference", Kind::Text } };
	pychecks::checkKeywords(kw, fields);
	pychecks::ctorKeywords(*this, kw, { "lawSumSteps" });
}

void MesoBackgroundDamping::registerChecked(boost::python::object& cls)
{
	pychecks::checked(cls, "gammaB", &MesoBackgroundDamping::gammaB);
	pychecks::checked(cls, "gammaBR", &MesoBackgroundDamping::gammaBR);
	pychecks::checked(cls, "reference", &MesoBackgroundDamping::reference);
}

void MesoBackgroundDamping::sumNeighbours()
{
	// One pass over the contacts (a vector) instead of each body's map of interactions: every
	// contact adds each body's motion to the other's sums, in the container's order (the law's).
	const BodyContainer& bodies = *scene->bodies;
	const size_t         n      = bodies.size();
	neighbours.assign(n, Neighbours());
	isSphere.assign(n, 0);
	for (size_t id = 0; id < n; ++id)
		if (bodies[id]) isSphere[id] = dynamic_cast<const Sphere*>(bodies[id]->shape.get()) != nullptr;
	for (const auto& I : *scene->interactions) {
		if (!I->isReal()) continue;
		const auto* geom = dynamic_cast<const ScGeom*>(I->geom.get());
		if (!geom || !(geom->penetrationDepth > 0)) continue;
		const Body::id_t id1 = I->getId1(), id2 = I->getId2();
		if (!bodies[id1] || !bodies[id2]) continue;
		MesoNeighbourSums::sumPair(neighbours, *I, *geom, *bodies[id1]->state, *bodies[id2]->state, isSphere[id1], isSphere[id2], scene);
	}
}

MesoBackgroundDamping::Laws MesoBackgroundDamping::precedingLaws() const
{
	// The laws run right before this engine, provided they are all meso laws: then every contact in
	// overlap was visited by one of them, and nothing moved a body in between.
	Laws        laws;
	const auto& engines = scene->engines;
	for (size_t k = 1; k < engines.size(); ++k) {
		if (engines[k].get() != this) continue;
		const auto* loop = dynamic_cast<const InteractionLoop*>(engines[k - 1].get());
		if (!loop || loop->dead || !loop->lawDispatcher) return {};
		for (const auto& f : loop->lawDispatcher->functors) {
			auto law = YADE_PTR_DYN_CAST<Law2_ScGeom_MesoPhys_Meso>(f);
			if (!law) return {};
			laws.push_back(law);
		}
		return laws;
	}
	return {};
}

bool MesoBackgroundDamping::takeLawSums(const Laws& laws)
{
	const long n = static_cast<long>(scene->bodies->size());
	if (sums->step.load() != scene->iter || sums->perThread.empty() || static_cast<long>(sums->perThread[0].size()) != n) return false;
	if (laws != sumLaws) return false;   // the engines changed since the last step
	neighbours.swap(sums->perThread[0]); // zeroed again by prepareLawSums
	for (size_t t = 1; t < sums->perThread.size(); ++t)
		for (long id = 0; id < n; ++id) {
			const Neighbours& s = sums->perThread[t][id];
			if (s.n == 0) continue;
			Neighbours& acc = neighbours[id];
			acc.x += s.x;
			acc.v += s.v;
			acc.w += s.w;
			acc.n += s.n;
		}
	return true;
}

void MesoBackgroundDamping::prepareLawSums(const Laws& laws, long n)
{
	for (const auto& law : sumLaws) // handed to before, gone from the loop now: stop adding
		if (std::find(laws.begin(), laws.end(), law) == laws.end()) law->neighbourSums.reset();
	sumLaws = laws;
	sums->step.store(-1);
	if (laws.empty()) return;
#ifdef YADE_OPENMP
	const size_t threads = static_cast<size_t>(omp_get_max_threads());
#else
	const size_t threads = 1;
#endif
	sums->perThread.resize(threads);
	for (auto& acc : sums->perThread)
		acc.assign(n, Neighbours());
	for (const auto& law : laws)
		law->neighbourSums = sums;
	sums->step.store(scene->iter + 1);
}

void MesoBackgroundDamping::action()
{
	validate();
	const bool relative = reference == "contacts";
	const long n        = static_cast<long>(scene->bodies->size());
	const bool track    = scene->trackEnergy;
	const Real dt       = scene->dt;
	if (track) { // each one checked: a saved scene may carry them with different lengths
		for (auto* v : { &prevVel, &prevAngVel, &prevForce, &prevTorque })
			if (static_cast<long>(v->size()) < n) v->resize(n, Vector3r::Zero());
		if (static_cast<long>(hasPrev.size()) < n) hasPrev.resize(n, 0);
	}
	const BodyContainer& bodies  = *scene->bodies;
	const Laws           laws    = relative && sumInLaw ? precedingLaws() : Laws();
	const bool           fromLaw = relative && sumInLaw && takeLawSums(laws);
	if (relative && !fromLaw) sumNeighbours();
	if (fromLaw) ++lawSumSteps;
	Real dissipated = 0;
	Real worst      = 0; // the largest drag per step against inertia, gamma dt / m (or / I)
#ifdef YADE_OPENMP
#pragma omp parallel for reduction(+ : dissipated) reduction(max : worst) schedule(static)
#endif
	for (long id = 0; id < n; ++id) {
		const shared_ptr<Body>& b = bodies[id];
		if (!b || !b->isDynamic() || b->isClumpMember()) continue;
		const State& st     = *b->state;
		const auto*  sphere = dynamic_cast<const Sphere*>(b->shape.get());
		const Real   rot    = sphere ? gammaBR * sphere->radius * sphere->radius : 0;
		if (st.mass > 0) worst = std::max(worst, gammaB * dt / st.mass);
		if (rot > 0 && st.inertia.minCoeff() > 0) worst = std::max(worst, rot * dt / st.inertia.minCoeff());
		if (track && hasPrev[id]) {
			// The drag applied last step acted while the velocity went from prevVel to vel: its work,
			// in the leapfrog's own measure, is F . (v_prev + v) dt / 2 (exact for translation).
			dissipated -= prevForce[id].dot(prevVel[id] + st.vel) * 0.5 * dt;
			dissipated -= prevTorque[id].dot(prevAngVel[id] + st.angVel) * 0.5 * dt;
			hasPrev[id] = 0;
		}
		Vector3r vRef = Vector3r::Zero(), wRef = Vector3r::Zero();
		if (relative) { // the rigid motion of the contacts, at the body's centre; none without contacts
			const Neighbours& acc = neighbours[id];
			if (acc.n == 0) continue;
			const Real inv = Real(1) / acc.n;
			wRef           = acc.w * inv;
			vRef           = acc.v * inv + wRef.cross(st.pos - acc.x * inv);
		}
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
	// An explicit drag of gamma dt / m >= 1 reverses a body's velocity within one step (>= 2: it
	// grows without bound): no physics there. Refused, naming the coefficients and the step.
	if (!(worst < 1)) {
		std::ostringstream msg;
		msg.precision(17);
		msg << "MesoBackgroundDamping.gammaB = " << gammaB << ", gammaBR = " << gammaBR << " with O.dt = " << dt
		    << ": the drag reaches gamma dt / m = " << worst << " (mass, or inertia for gammaBR a^2) for a body; it must stay below 1"
		    << " (the explicit drag would reverse the velocity within a step): lower them or O.dt";
		throw std::runtime_error(msg.str());
	}
	if (relative && sumInLaw) prepareLawSums(laws, n);
	else if (!sumLaws.empty()) {
		for (const auto& law : sumLaws)
			law->neighbourSums.reset();
		sumLaws.clear();
	}
}

} // namespace yade
