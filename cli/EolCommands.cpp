#include "cli/CliCommands.h"
#include "cli/EolAuditCommand.h"
#include "cli/EolCertificateCommand.h"
#include "cli/EolCommand.h"
#include "cli/EolRecipeApproveCommand.h"
#include "cli/EolRecipeCheckCommand.h"
#include "cli/EolRecipeCreateCommand.h"
#include "cli/EolRecipeShowCommand.h"
#include "cli/EolRecipeSignCommand.h"
#include "cli/EolResultsCommand.h"
#include "cli/EolRunCommand.h"
#include "cli/EolUserCommand.h"

namespace opentop {

void addEolCommands(CliCommandList& list)
{
    auto eol = std::make_unique<EolCommand>();
    eol->add(std::make_unique<EolRunCommand>());
    eol->add(std::make_unique<EolRecipeCreateCommand>());
    eol->add(std::make_unique<EolRecipeCheckCommand>());
    eol->add(std::make_unique<EolRecipeSignCommand>());
    eol->add(std::make_unique<EolRecipeShowCommand>());
    eol->add(std::make_unique<EolResultsCommand>());
    eol->add(std::make_unique<EolCertificateCommand>());
    eol->add(std::make_unique<EolRecipeApproveCommand>());
    eol->add(std::make_unique<EolUserCommand>(EolUserCommand::Action::Add));
    eol->add(std::make_unique<EolUserCommand>(EolUserCommand::Action::List));
    eol->add(std::make_unique<EolUserCommand>(EolUserCommand::Action::Disable));
    eol->add(std::make_unique<EolUserCommand>(EolUserCommand::Action::Passwd));
    eol->add(std::make_unique<EolAuditCommand>());
    list.push_back(std::move(eol));
}

} // namespace opentop
