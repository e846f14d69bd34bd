#include "CliCommands.h"
#include "EolAuditCommand.h"
#include "EolCertificateCommand.h"
#include "EolCommand.h"
#include "EolRecipeApproveCommand.h"
#include "EolRecipeCheckCommand.h"
#include "EolRecipeCreateCommand.h"
#include "EolRecipeShowCommand.h"
#include "EolRecipeSignCommand.h"
#include "EolResultsCommand.h"
#include "EolRunCommand.h"
#include "EolUserCommand.h"

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
