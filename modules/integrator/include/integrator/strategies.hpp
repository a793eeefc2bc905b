#pragma once
// The five strategies of contact_strategy.hpp (one file each in src/) and what they share.
#include "integrator/contact_strategy.hpp"

#include <vector>

namespace sig {

class SignoriniStrategy final : public ContactStrategy {
public:
  using ContactStrategy::ContactStrategy;
  std::string name() const override { return "signorini"; }

protected:
  std::vector<ContactLaw> first_laws(const ContactSetting& setting,
                                     const ContactStepStart& start) const override;
  ContactStepSolution phases(ContactBulk& bulk, const ContactSetting& first,
                             const ContactStepStart& start) const override;
};

class ComplianceStrategy final : public ContactStrategy {
public:
  using ContactStrategy::ContactStrategy;
  std::string name() const override { return "compliance"; }

protected:
  std::vector<ContactLaw> first_laws(const ContactSetting& setting,
                                     const ContactStepStart& start) const override;
  ContactStepSolution phases(ContactBulk& bulk, const ContactSetting& first,
                             const ContactStepStart& start) const override;
};

class SpecificPenaltyStrategy final : public ContactStrategy {
public:
  using ContactStrategy::ContactStrategy;
  std::string name() const override { return "specific-penalty"; }

protected:
  std::vector<ContactLaw> first_laws(const ContactSetting& setting,
                                     const ContactStepStart& start) const override;
  ContactStepSolution phases(ContactBulk& bulk, const ContactSetting& first,
                             const ContactStepStart& start) const override;
};

class TwoStepStrategy final : public ContactStrategy {
public:
  using ContactStrategy::ContactStrategy;
  std::string name() const override { return "two-step"; }

protected:
  std::vector<ContactLaw> first_laws(const ContactSetting& setting,
                                     const ContactStepStart& start) const override;
  ContactStepSolution phases(ContactBulk& bulk, const ContactSetting& first,
                             const ContactStepStart& start) const override;
};

class ImprovedPenaltyStrategy final : public ContactStrategy {
public:
  using ContactStrategy::ContactStrategy;
  std::string name() const override { return "ipm"; }

protected:
  std::vector<ContactLaw> first_laws(const ContactSetting& setting,
                                     const ContactStepStart& start) const override;
  ContactStepSolution phases(ContactBulk& bulk, const ContactSetting& first,
                             const ContactStepStart& start) const override;
};

/// The CONT laws with their normal law replaced by `normal` (compliance or
/// compliance-unilateral) of slope r as its secant from the penetrations at the start of the
/// step (contact_law.hpp), friction and wall depth kept (contact_strategy.cpp).
std::vector<ContactLaw> secant_compliance(const ContactSetting& setting,
                                          const ContactStepStart& start, double r,
                                          NormalLaw normal);

} // namespace sig
