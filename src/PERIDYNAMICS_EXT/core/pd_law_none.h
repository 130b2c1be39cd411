/* No failure law: no bond breaks, but some may be broken already (a
 * pre-crack), so the loop still decodes them. */
#ifndef PD_LAW_NONE_H
#define PD_LAW_NONE_H

#include "pd_failure.h"

PD_INLINE int pd_law_none_now(const pd_failure *f, const pd_bond *bd, double eps,
                                  const pd_bond_force *bf)
{
  (void) f, (void) bd, (void) eps, (void) bf;
  return 0;
}

PD_INLINE int pd_law_none_after(const pd_failure *f, const pd_bond *bd, double eps)
{
  (void) f, (void) bd, (void) eps;
  return 0;
}

PD_INLINE int pd_law_none_ahead(const pd_failure *f, const pd_bond *bd, double eps,
                                    const pd_bond_force *bf)
{
  (void) f, (void) bd, (void) eps, (void) bf;
  return 0;
}

PD_INLINE int pd_law_none_takes_notes(void) { return PD_NOTES_NONE; }

PD_INLINE double pd_law_none_notes(const pd_failure *f, const pd_bond *bd)
{
  (void) f, (void) bd;
  return 0.0;
}

#endif
