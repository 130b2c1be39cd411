/* The failure laws, registered here once. Each law lives in its own
 * header (pd_law_<name>.h): its parameters, the questions the bond loop
 * asks it and what it notes (pd_bond_loop.h):
 *   pd_law_<name>_now   does an intact bond break in this evaluation,
 *                       before its force acts (it then acts with half)?
 *   pd_law_<name>_after does it break after its force acted?
 *   pd_law_<name>_ahead might it break now or after? Yes whenever _now or
 *                       _after would (it may say yes when neither does):
 *                       the vectorized pass asks only this cheap screen,
 *                       without the exact tests' per-atom loads, and a yes
 *                       takes the bond's chunk bond by bond, where _now and
 *                       _after decide;
 *   pd_law_<name>_notes what the law keeps of every intact bond that acted
 *                       (a number per bond, e.g. a candidate for its ends'
 *                       state). The loop gives the law each atom's largest
 *                       (pd_failure.note_atom, owned and ghost atoms, -inf
 *                       where no bond noted; a NaN is ignored), so notes
 *                       combine by their maximum, in any order. An
 *                       evaluation whose law needs no notes gives no
 *                       array (note_atom NULL): the loop keeps none then.
 *   pd_law_<name>_takes_notes  what the law's kernels keep of the notes:
 *                       PD_NOTES_NONE (they neither ask _notes nor keep
 *                       any), PD_NOTES_ENDS (each atom's largest, above)
 *                       or PD_NOTES_LARGEST (only the largest of the
 *                       evaluation: pd_failure.note_largest, no array).
 * _now, _after, _ahead and _notes only answer (no side effects): the loop
 * asks _ahead and _notes for a row's bonds ahead of their turn, in its
 * vectorized pass, and _now, _after and _notes again bond by bond.
 * To add a law: write its header, add one line to the list below and its
 * #include to pd_law_hooks.h. */
#ifndef PD_LAWS_H
#define PD_LAWS_H

/* X(ID, name): PD_FAIL_<ID> in pd_fail_law; hooks pd_law_<name>_now/_after/_ahead/_notes
 * and _takes_notes. */
#define PD_FAILURE_LAWS(X, ...)          \
  X(NONE, none, __VA_ARGS__)             \
  X(STRETCH, stretch, __VA_ARGS__)       \
  X(ENERGY, energy, __VA_ARGS__)         \
  X(LEGACY, legacy, __VA_ARGS__)         \
  X(LEGACY_GUARDED, legacy_guarded, __VA_ARGS__)

/* pd_law_<name>_takes_notes */
enum { PD_NOTES_NONE, PD_NOTES_ENDS, PD_NOTES_LARGEST };

#define PD_LAW_ENUM(ID, name, ...) PD_FAIL_##ID,
typedef enum pd_fail_law { PD_FAILURE_LAWS(PD_LAW_ENUM, ~) PD_NLAWS } pd_fail_law;
#undef PD_LAW_ENUM

#endif
