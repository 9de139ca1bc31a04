// Every number a MesoMat declares, each once. The core's MaterialParams, its validation and mixing,
// the pair's serialization, YADE's MesoMat attributes (with their docs and Python checks), their
// parsing, Ip2.mixedParameters and the MesoPhys properties are generated from these two lists; a
// new parameter is one line here plus the physics that reads it. No YADE here.
//
// Columns of X(name, default, unit, ok, rule, mix, dest, doc):
//   name     the attribute of MesoMat and the field of MaterialParams
//   default  of a new MesoMat
//   unit     SI, appended to the doc
//   ok, rule a condition on the value v (the parameters listed before it are valid in m) and the words
//            of the error when it fails; every value must also be finite
//   mix      how two materials mix: harmonic (2xy/(x+y), 0 if either is 0: a material without a
//            mechanism switches it off for its pairs), arithmetic, or smaller
//   dest     where the mixed value goes in PairParams
//   doc      for YADE's documentation
// Relations beyond "the value and the ones before it" (kca > 0 when fa > 0; fa needs an adhesion
// mode) are checked in validate(). The first two lists are apart because MesoMat's text attributes
// (adhesion, k2Interpolation) lie between them in its saved layout. A new entry goes into the third
// list, which MesoMat and PairParams save after everything else, each entry from the class versions
// given for it below (raise both classes' versions in MesoContact.hpp to them), so that files of
// earlier versions still load, with the entry at its default.
#pragma once

// clang-format off
// The normal law; each is the field of PairParams of the same name.
#define MESO_NORMAL_PARAMS(X) \
	X(k1,     1e2, "N/m",  v > 0,           "the loading stiffness must be > 0",               harmonic,   k1,     "Plastic (initial) loading stiffness $k_1$, > 0") \
	X(kp,     5e2, "N/m",  v >= m.k1,       "the limit stiffness must be >= k1",               harmonic,   kp,     "Elastic limit stiffness $k_p\\geq k_1$; $k_p=k_1$ gives a linear elastic contact") \
	X(kc,     0,   "N/m",  v >= 0,          "the adhesive stiffness must be >= 0",             harmonic,   kc,     "Adhesive stiffness $k_c\\geq 0$ of the tensile branch $f=-k_c\\delta$") \
	X(phiF,   0.1, "-",    v > 0 && v <= 1, "the plasticity depth must lie in (0, 1]",         arithmetic, phiF,   "Dimensionless plasticity depth $\\phi_f\\in(0,1]$: the limit branch starts at $\\delta_{max}^p=k_p/(k_p-k_1)\\,\\phi_f a_{12}$") \
	X(fa,     0,   "N",    v >= 0,          "the non-contact adhesive force must be >= 0",     harmonic,   fa,     "Non-contact adhesive force magnitude $f_a\\geq 0$; needs ``adhesion`` other than 'none' and $k_{ca}>0$") \
	X(kca,    0,   "N/m",  v >= 0,          "the non-contact adhesive stiffness must be >= 0", harmonic,   kca,    "Non-contact adhesive stiffness $k_{ca}$; the non-contact force acts down to the overlap $\\delta_a=-f_a/k_{ca}$") \
	X(gammaN, 0,   "kg/s", v >= 0,          "the viscous damping must be >= 0",                harmonic,   gammaN, "Normal viscous damping coefficient $\\gamma_0\\geq 0$; the force $\\gamma_0 v_n$ acts in mechanical contact")

// The Luding 2008 elements (all off by default). The static sliding coefficient muS is
// tan(frictionAngle), YADE's FrictMat attribute, so it is not listed.
#define MESO_TANGENTIAL_PARAMS(X) \
	X(phiD,   1, "-",    v > 0 && v <= 1, "the dynamic/static friction ratio must lie in (0, 1]", smaller, phiD, "Ratio $\\phi_d=\\mu_d/\\mu_s\\in(0,1]$ of the dynamic to the static Coulomb limit, for sliding, rolling and torsion. The static sliding coefficient is $\\mu_s=\\tan$ :yref:`frictionAngle<FrictMat.frictionAngle>`") \
	X(kt,     0, "N/m",  v >= 0, "must be >= 0", harmonic, sliding.k,     "Sliding spring stiffness $k_t$; sliding acts when $k_t$ or $\\gamma_t$ is > 0 (off by default)") \
	X(gammaT, 0, "kg/s", v >= 0, "must be >= 0", harmonic, sliding.gamma, "Sliding dashpot $\\gamma_t$") \
	X(kr,     0, "N/m",  v >= 0, "must be >= 0", harmonic, rolling.k,     "Rolling spring stiffness $k_r$; rolling acts on :yref:`ScGeom6D` contacts only") \
	X(gammaR, 0, "kg/s", v >= 0, "must be >= 0", harmonic, rolling.gamma, "Rolling dashpot $\\gamma_r$") \
	X(muR,    0, "-",    v >= 0, "must be >= 0", smaller,  rolling.muS,   "Rolling Coulomb coefficient $\\mu_r$") \
	X(ko,     0, "N/m",  v >= 0, "must be >= 0", harmonic, torsion.k,     "Torsion spring stiffness $k_o$; torsion acts on :yref:`ScGeom6D` contacts only") \
	X(gammaO, 0, "kg/s", v >= 0, "must be >= 0", harmonic, torsion.gamma, "Torsion dashpot $\\gamma_o$") \
	X(muO,    0, "-",    v >= 0, "must be >= 0", smaller,  torsion.muS,   "Torsion Coulomb coefficient $\\mu_o$")
// clang-format on

// clang-format off
// Added after the first saved layout, saved last. Each entry needs MESO_SINCE_MAT_<name> and
// MESO_SINCE_PAIR_<name>: the MesoMat and PairParams versions that first save it (a missing one does
// not compile). gammaN2: a dashpot whose force grows with the square of the normal speed, for a loss
// per cycle that grows faster than the loading rate (docs/model.md §5).
#define MESO_ADDED_PARAMS(X) \
	X(gammaN2, 0, "kg/m", v >= 0, "the quadratic viscous damping must be >= 0", harmonic, gammaN2, "Quadratic normal dashpot $\\gamma_2\\geq 0$: the force $\\gamma_2|v_n|v_n$ acts in mechanical contact beside $\\gamma_0 v_n$ (0: off)")
// clang-format on
#define MESO_SINCE_MAT_gammaN2 1
#define MESO_SINCE_PAIR_gammaN2 2

// Every list, in MesoMat's attribute order apart from the text attributes.
#define MESO_ALL_PARAMS(X) MESO_NORMAL_PARAMS(X) MESO_TANGENTIAL_PARAMS(X) MESO_ADDED_PARAMS(X)
