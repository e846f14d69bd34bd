#include "CliCommands.h"
#include "EolCertificateCommand.h"
#include "EolCommand.h"
#include "EolRecipeCheckCommand.h"
#include "EolRecipeCreateCommand.h"
#include "EolRecipeShowCommand.h"
#include "EolRecipeSignCommand.h"
#include "EolResultsCommand.h"
#include "EolRunCommand.h"

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
    list.push_back(std::move(eol));
}

} // namespace opentop
