// Parameters of the meso-particle contact law (Singh, Magnanimo & Luding): per material, their
// validation, and the mixing of two materials into the parameters of one pair. No YADE here.
#pragma once
#include "MesoParamTable.hpp"
#include <string>

// Small functions of the hot path (Law2::go()): GCC does not inline them on its own in -fPIC code.
// The other inline functions of the core are hidden: in a plugin a visible inline function is called
// through the PLT (it could be interposed), which costs Law2::go() a jump per call.
#if defined(__GNUC__)
#define MESO_HOT inline __attribute__((always_inline))
#define MESO_INLINE inline __attribute__((visibility("hidden")))
#else
#define MESO_HOT inline
#define MESO_INLINE inline
#endif

namespace meso {

// The adhesion modes (docs/model.md §4), one row each; a new mode is a row here and its force in
// NormalLaw.hpp's adhesiveForce. X(enumerator, saved value, name, strength, acrossGap, doc):
// a mixed pair takes the mode of lower strength; a mode that acts across the gap pulls pairs in
// before they touch, so the collider must find them at the force's range (Ip2 warns otherwise);
// the others start at the first touch (the 'touched' flag) or never.
#define MESO_ADHESION_MODES(X)                                                                                                                                 \
	X(None, 0, "none", 0, false, "no non-contact force")                                                                                                   \
	X(Reversible, 1, "reversible", 2, true, "Eq. 14: pull-in and pull-off along $-k_{ca}\\delta-f_a$")                                                     \
	X(JumpIn, 2, "jumpIn", 1, false, "Eq. 15: no force before first touch, $-f_a$ in contact, pull-off tail after")

// The modes as documentation: "'none' (no non-contact force); ..." (MesoMat.adhesion's doc).
#define MESO_ADHESION_DOC(e, value, name, strength, acrossGap, doc) "'" name "' (" doc "); "

#define MESO_ADHESION_ENUM(e, value, ...) e = value,
enum class Adhesion : int { MESO_ADHESION_MODES(MESO_ADHESION_ENUM) };
#undef MESO_ADHESION_ENUM
enum class K2Interpolation : int { Linear = 0, Sqrt = 1 };

struct AdhesionMode {
	Adhesion    mode;
	const char* name;
	int         strength;
	bool        acrossGap;
};
#define MESO_ADHESION_ROW(e, value, name, strength, acrossGap, ...) AdhesionMode { Adhesion::e, name, strength, acrossGap },
constexpr AdhesionMode kAdhesionModes[] = { MESO_ADHESION_MODES(MESO_ADHESION_ROW) };
#undef MESO_ADHESION_ROW
constexpr int kAdhesionModeCount = sizeof(kAdhesionModes) / sizeof(kAdhesionModes[0]);

// The row of a mode (the enumerators are the rows' indices: checked below).
constexpr const AdhesionMode& adhesionMode(Adhesion a) { return kAdhesionModes[static_cast<int>(a)]; }
#define MESO_ADHESION_INDEX(e, value, ...) static_assert(kAdhesionModes[value].mode == Adhesion::e, "rows in saved-value order");
MESO_ADHESION_MODES(MESO_ADHESION_INDEX)
#undef MESO_ADHESION_INDEX

// For the hot path: the modes that act across the gap, as comparisons with constants (no table load).
#define MESO_ADHESION_ACROSS(e, value, name, strength, acrossGap, ...) (acrossGap && a == Adhesion::e) ||
constexpr bool actsAcrossGap(Adhesion a) { return MESO_ADHESION_MODES(MESO_ADHESION_ACROSS) false; }
#undef MESO_ADHESION_ACROSS

Adhesion        parseAdhesion(const std::string& name);        // throws std::invalid_argument naming 'adhesion'
K2Interpolation parseK2Interpolation(const std::string& name); // throws naming 'k2Interpolation'
const char*     adhesionName(Adhesion a);
const char*     k2InterpolationName(K2Interpolation k);
std::string     adhesionChoices(); // "'none', 'reversible' or 'jumpIn'", for messages

// One spring-dashpot-Coulomb element (sliding, rolling or torsion): spring k [N/m], dashpot
// gamma [kg/s], static and dynamic coefficients of the Coulomb limit [-].
struct ElementParams {
	double k = 0, gamma = 0, muS = 0, muD = 0;
	bool   active() const { return k > 0 || gamma > 0; }
};

// What a material declares (docs/model.md §2); SI units. The numbers are those of MesoParamTable.hpp.
struct MaterialParams {
#define MESO_FIELD(name, def, ...) double name = def;
	MESO_ALL_PARAMS(MESO_FIELD)
#undef MESO_FIELD
	double          muS             = 0; // static sliding coefficient, tan(frictionAngle) of YADE's FrictMat [-]
	Adhesion        adhesion        = Adhesion::None;
	K2Interpolation k2Interpolation = K2Interpolation::Linear;
	// A dominant material imposes its own parameters on its pairs with non-dominant materials
	// (no mixing): walls whose law is prescribed, like Luding's adhesive loading walls.
	bool dominant = false;
};

// Throws std::invalid_argument whose message starts with the offending parameter's name.
// Every nonzero number a material or pair holds lies in [kSmallestValue, kLargestValue] in magnitude.
constexpr double kSmallestValue = 1e-100, kLargestValue = 1e100;

void validate(const MaterialParams& m);

// Harmonic mean 2xy/(x+y) (0 if either is 0), without overflow for any finite x, y >= 0; x for x == y.
double harmonicMean(double x, double y);

// The parameters of one material pair (docs/model.md §8): the same for every contact of that pair,
// so YADE contacts share one copy (a contact's memory is what bulk runs pay for, per step).
struct PairParams {
	// Hot: what Law2::go() reads every step, flags first.
	bool            tangential       = false;                                      // any tangential mechanism acts
	bool            rollingOrTorsion = false;                                      // rolling and torsion act (ScGeom6D and a spring or dashpot set)
	bool            slidingActs = false, rollingActs = false, torsionActs = false; // which elements act (setMechanisms())
	Adhesion        adhesion        = Adhesion::None;
	K2Interpolation k2Interpolation = K2Interpolation::Linear;
	double          k1 = 0, kp = 0, kc = 0, fa = 0, kca = 0, gammaN = 0, gammaN2 = 0;
	double          deltaA        = 0;         // range of the non-contact force -fa/kca (<= 0) [m]
	double          delta0PerMaxP = 0;         // delta0P/deltaMaxP = 1 - k1/kp (Eqs. 10, 11) [-]
	ElementParams   sliding, rolling, torsion; // Luding 2008 tangential elements
	double          leverFactor = 1;           // rolling/torsion arm: 1 -> a1'a2'/(a1'+a2'), 2 -> 2 a1'a2'/(a1'+a2')
	// Cold: kept for the user and to derive the geometry.
	double phiF = 0; // plasticity depth [-]
	double phiD = 1; // dynamic/static ratio of the Coulomb limits (the elements' muD already hold it) [-]
};

// The first parameter in which two pairs' parameters differ ("" when they are the same): what a
// contact carries against what its bodies' materials give it now.
std::string firstDifference(const PairParams& a, const PairParams& b);

// What one contact adds to its pair's parameters: the radii and the limit overlap, which scales with a12.
struct PairGeometry {
	double invDeltaMaxP = 0;         // 1/deltaMaxP (0 if kp == k1) [1/m]; first: the normal law reads only this
	double radius1 = 0, radius2 = 0; // sphere radii; 0 for a wall, box or facet [m]
	int    meshFacet = -1;           // a facet contact: the facet of the mesh it lies on now (-1: the one that made it)
	double a12() const { return reducedRadius(radius1, radius2); }
	// Limit overlap kp/(kp-k1) phiF a12 (Eq. 10), +inf if kp == k1 [m]; kept as its inverse, which the hot path uses.
	double deltaMaxP() const { return 1 / invDeltaMaxP; }
	// Plastic overlap on the limit branch phiF a12 (Eq. 11) [m].
	double delta0P(const PairParams& p) const { return p.phiF * a12(); }
	// Reduced radius 2 a1 a2/(a1+a2) of two spheres; against a wall, box or facet (radius 0) 2 a.
	static double reducedRadius(double r1, double r2) { return (r1 > 0 && r2 > 0) ? harmonicMean(r1, r2) : 2 * (r1 > 0 ? r1 : r2); }
};

// A pair's parameters as read from a file: every number against its material rule (validate), the
// mode enums in range, the derived values and flags as mixPair and setMechanisms make them. Throws
// std::invalid_argument naming the field.
void validatePair(const PairParams& p);

// Mixes two materials: stiffnesses, fa and dashpots by harmonic mean; phiF by arithmetic mean;
// friction coefficients by the smaller one (as YADE's Ip2_FrictMat_FrictMat_FrictPhys); phiD by the smaller;
// adhesion is the weaker mode of the two (None < JumpIn < Reversible); the sqrt interpolation
// only when both ask for it. Equal materials give their own values. When exactly one of the two is
// dominant, the pair takes that material's parameters unmixed. The flags (setMechanisms()) and the
// leverFactor are left to the caller.
PairParams mixPair(const MaterialParams& m1, const MaterialParams& m2);

// Sets the flags tangential, rollingOrTorsion, slidingActs, rollingActs and torsionActs from the
// elements; rolling and torsion need a geometry that carries rotations (YADE: ScGeom6D).
void setMechanisms(PairParams& p, bool geometryWithRotations);

// The geometry of one contact of pair p between spheres of radii r1 and r2 (0: wall, box or facet).
PairGeometry pairGeometry(const PairParams& p, double radius1, double radius2);

// Largest stable step of the leapfrog (central difference) integration of a spring k [N/m] with a
// dashpot gamma [kg/s] on a mass m = 1/invMass: (2/w)(sqrt(1 + z^2) - z), w = sqrt(k/m), z = gamma/(2 sqrt(k m));
// 2 m/gamma for a dashpot alone; +inf without either or for an infinite mass (invMass = 0) [s].
double stableStep(double k, double gamma, double invMass);

} // namespace meso
