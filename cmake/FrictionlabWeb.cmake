# The browser page (web/): TypeScript bundled by esbuild, with the npm packages package-lock.json
# pins, installed by `npm ci` at build time (never at run time). Built beside the executable
# (src/cli/web/), where `frictionlab serve` looks for it. ON when Node.js and npm are found.
find_program(FRICTIONLAB_NODE node)
find_program(FRICTIONLAB_NPM npm)
set(web_default OFF)
if(FRICTIONLAB_NODE AND FRICTIONLAB_NPM AND FRICTIONLAB_WITH_SERVE)
  set(web_default ON)
endif()
option(FRICTIONLAB_WITH_WEB "The browser page of frictionlab serve (web/; Node.js and npm)"
       ${web_default})
if(FRICTIONLAB_WITH_WEB AND NOT (FRICTIONLAB_NODE AND FRICTIONLAB_NPM))
  message(FATAL_ERROR "FRICTIONLAB_WITH_WEB=ON but node or npm was not found (apt-get install nodejs npm)")
endif()

if(FRICTIONLAB_WITH_WEB)
  set(web_source ${PROJECT_SOURCE_DIR}/web)
  set(FRICTIONLAB_WEB_DIR ${PROJECT_BINARY_DIR}/src/cli/web)
  set(web_installed ${PROJECT_BINARY_DIR}/web-npm-ci.stamp)
  add_custom_command(
    OUTPUT ${web_installed}
    COMMAND ${FRICTIONLAB_NPM} ci --no-audit --no-fund --loglevel=error
    COMMAND ${CMAKE_COMMAND} -E touch ${web_installed}
    DEPENDS ${web_source}/package.json ${web_source}/package-lock.json
    WORKING_DIRECTORY ${web_source}
    COMMENT "web: npm ci (the packages package-lock.json pins)"
    VERBATIM)
  # The page's catalogues are bundled in: a new assets/locales/TAG.ftl is a new language.
  file(GLOB_RECURSE web_inputs CONFIGURE_DEPENDS ${web_source}/src/*.ts
       ${PROJECT_SOURCE_DIR}/assets/locales/*.ftl)
  list(APPEND web_inputs ${web_source}/index.html ${web_source}/class.html ${web_source}/app.css
       ${web_source}/build.mjs ${web_source}/catalogues.mjs)
  # The lab's page (index.html, app.js) and the teacher's class table (class.html, class.js).
  add_custom_command(
    OUTPUT ${FRICTIONLAB_WEB_DIR}/app.js ${FRICTIONLAB_WEB_DIR}/index.html
           ${FRICTIONLAB_WEB_DIR}/class.js ${FRICTIONLAB_WEB_DIR}/class.html
           ${FRICTIONLAB_WEB_DIR}/app.css
    COMMAND ${FRICTIONLAB_NODE} build.mjs ${FRICTIONLAB_WEB_DIR}
    DEPENDS ${web_installed} ${web_inputs}
    WORKING_DIRECTORY ${web_source}
    COMMENT "web: the page bundled into ${FRICTIONLAB_WEB_DIR}"
    VERBATIM)
  add_custom_target(frictionlab-web ALL DEPENDS ${FRICTIONLAB_WEB_DIR}/app.js
                                                ${FRICTIONLAB_WEB_DIR}/class.js)
endif()
