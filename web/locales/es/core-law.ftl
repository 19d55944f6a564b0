# Los mensajes del núcleo sobre la ley propia de un paso: por qué se rechazó una fórmula y el
# veredicto sobre una ley frente a la dinámica del error que su paso debe dar. La CLI los dice en
# inglés; la página, en el idioma del lector. Los nombres (x1h, k1s1, v1, z2), las funciones (sqrt),
# las fórmulas (ż1 = −k1·z1 + z2, a3·ω_d), los ajustes (law.v1), los números de ecuación del
# artículo ((28)) y la entrada citada se mantienen tal cual. La entrada citada conserva sus comillas.

## A formula refused


## A step's own law refused or missing


## The verdict on a step's own law

# $designed es la dinámica del error diseñada del paso (ż1 = −k1·z1 + z2); $output, el control
# virtual que da la ley (v1); $own es yes cuando el paso se juzga sobre la ley propia del paso
# anterior, $before (v1 o v3); $worst, la diferencia relativa a su tamaño (2e-16); $draws, cuántos
# estados se sortearon; $caveats, uno de los mensajes law-caveat-*.
law-designed = Tu paso { $step } da la dinámica diseñada { $designed }{ $own ->
        [yes] {" "}con tu propio { $before }: tu { $output } coincide con el que la da
       *[no] : tu { $output } coincide con el del artículo
    }, con una diferencia relativa de { $worst } como máximo en { $draws } estados y valores de parámetros sorteados.{ $caveats }
# Como law-designed; $unit es la unidad de $output; $difference es law-difference o
# law-difference-unnamed.
law-not-designed = Tu paso { $step } no da la dinámica diseñada { $designed }{ $own ->
        [yes] {" "}con tu propio { $before }: tu { $output } ({ $unit }) no coincide con el que la da
       *[no] : tu { $output } ({ $unit }) no coincide con el del artículo
    }; la diferencia relativa llega a { $worst } en { $draws } estados sorteados. { $difference }{ $caveats }
# $cause es uno de los mensajes law-never-runs … law-not-finite.
law-not-designed-because = Tu paso { $step } no da la dinámica diseñada { $designed }: { $cause }.
law-cannot-judge = Tu paso { $step } no se puede evaluar: { $cause }.
# $finding es uno de los mensajes law-term-*, law-mistake-*, law-scenario-values-only y
# law-rate-of-z.
law-difference = La diferencia: { $finding }.
law-difference-unnamed = La diferencia no es un término de la ley del artículo: compara tu ley con la deducción del paso término a término.

## What a verdict adds after its sentence (each caveat starts with the space after the sentence)

law-caveat-none = {""}
# $names enumera los nombres que lee la ley propia del paso anterior cuyas derivadas no se conocen.
law-caveat-unchained = {" "}Tu { $before } lee { $names }, y el lazo no tiene su derivada (contiene la tensión que elige un paso posterior, o una derivada que el lazo no tiene), así que este paso se juzga sobre el { $before } del artículo.
law-caveat-failed = {" "}Tu { $before } no da un valor finito en { $failed } de los { $draws } estados sorteados, en los que este paso no se juzga.
# Ambas advertencias: $unread es law-caveat-unchained; $failing, law-caveat-failed.
law-caveat-both = { $unread }{ $failing }

## Why a law's distance from its designed dynamics is not a number


## What a wrong law gets wrong

# $term es un término de la ley del artículo con su signo (+a3·ω_d).
law-term = el término { $term }
# $part es una parte del término $term, desarrollado.
law-term-part = la parte { $part } del término { $term }
# $label es law-term o law-term-part.
law-term-missing = falta { $label } de la ley del artículo
law-term-wrong-sign = { $label } tiene el signo cambiado
law-term-twice = { $label } aparece dos veces
# $factor es cuántas veces contiene la ley el término del artículo.
law-term-scaled = { $label } vale { $factor } veces lo que debería
law-scenario-values-only = coincide con la ley del artículo solo con los valores de parámetros y ganancias de este escenario: un parámetro o una ganancia está escrito como su número donde la ley necesita su nombre
# La ley es la del artículo menos (o más) $gain por el error $z del paso (z1): $now es la tasa a la
# que decae entonces su error; $meant, la diseñada.
law-rate-of-z = es la ley del artículo { $sign ->
        [minus] menos
       *[plus] más
    } { $gain }·{ $z }: con los parámetros de este escenario, tu { $z } decae a una tasa de { $now } /s, no de { $meant } /s; revisa la ganancia y el signo de tus términos en { $z }

## Slips students make, named when a law equals one

law-mistake-k1 = tiene k1 donde la (28) tiene k1s1 = k1 − a3
law-mistake-a3-x1h = tiene a3·x̂1 donde la (27) tiene a3·ω_d
law-mistake-k2 = tiene k2 donde la (36) tiene k2s1 = k2 − a7 − a8: queda entonces el −(a7 + a8)·z2 de ż2
law-mistake-printed-dv1 = toma v̇1 tal como lo imprime la (31), con sus dos erratas: a3·ω_d donde la derivada de a3·ω_d es a3·ω̇_d, y â2 donde la derivada de â2 es su tasa de cambio (0 con una carga conocida)
law-mistake-printed-dv1-wd = toma v̇1 tal como lo imprime la (31), con a3·ω_d donde la derivada de a3·ω_d es a3·ω̇_d
law-mistake-printed-dv1-a2 = toma v̇1 tal como lo imprime la (31), con â2 donde la derivada de â2 es su tasa de cambio (0 con una carga conocida)
law-mistake-robust-2 = escribe el término robusto −h2²/(4·ε2)·z2 de la (38) sin el interruptor robust, así que actúa aunque los términos robustos estén desactivados
law-mistake-psi-modulus = toma ψ_d como el módulo del flujo (ψ_d²), mientras que la z3 = x̂4² + x̂5² − ψ_d del artículo lo toma como el módulo al cuadrado
law-mistake-factor-2 = omite el factor 2 en todo ψ3: la derivada de x̂4² + x̂5² es 2·(x̂4·x̂̇4 + x̂5·x̂̇5)
law-mistake-residual-rates = omite los términos de la regla de la cadena de los residuos 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 y 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 de ψ4
law-mistake-drifts = tiene las derivas del modelo f̂4, f̂5 donde ψ4 tiene las derivadas del observador x̂̇4 = f̂4 + si4 y x̂̇5 = f̂5 + si5: faltan las inyecciones
law-mistake-drift-4 = tiene la deriva del modelo f̂4 donde ψ4 tiene la derivada del observador x̂̇4 = f̂4 + si4: falta la inyección si4
law-mistake-drift-5 = tiene la deriva del modelo f̂5 donde ψ4 tiene la derivada del observador x̂̇5 = f̂5 + si5: falta la inyección si5
law-mistake-factor-si4 = el factor de x̂̇4 omite si4: la derivada de 2·x̂4·si4 en ψ3 da 2·si4·x̂̇4
law-mistake-factor-si5 = el factor de x̂̇5 omite si5: la derivada de 2·x̂5·si5 en ψ3 da 2·si5·x̂̇5
law-mistake-robust-4 = escribe el término robusto −h4²/(4·ε4)·z4 de la (53) sin el interruptor robust, así que actúa aunque los términos robustos estén desactivados

## The names a law may use: what each one means (its name, symbol and unit are shown beside it)

formula-name-x1h = velocidad del rotor estimada ω̂ (x̂1 a posteriori)
formula-name-x2h = corriente estatórica estimada î_sa
formula-name-x3h = corriente estatórica estimada î_sb
formula-name-x4h = flujo rotórico estimado φ̂_ra
formula-name-x5h = flujo rotórico estimado φ̂_rb
formula-name-x2 = corriente estatórica medida i_sa
formula-name-x3 = corriente estatórica medida i_sb
formula-name-xt2 = residuo x̃2 = x2 − x̂2
formula-name-xt3 = residuo x̃3 = x3 − x̂3
formula-name-dxt2 = derivada nominal de x̃2: −(a7 + l21)·x̃2 − l22·x̃3
formula-name-dxt3 = derivada nominal de x̃3: −l31·x̃2 − (a7 + l32)·x̃3
formula-name-dx4h = derivada de x̂4 en el observador: −a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4
formula-name-dx5h = derivada de x̂5 en el observador: −a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5
formula-name-wd = referencia de velocidad ω_d
formula-name-dwd = su primera derivada
formula-name-ddwd = su segunda derivada
formula-name-psi-d = consigna de flujo para x̂4² + x̂5²
formula-name-si1 = inyección del observador en x̂1: l11·x̃2 + l12·x̃3
formula-name-si2 = inyección del observador en x̂2
formula-name-si3 = inyección del observador en x̂3
formula-name-si4 = inyección del observador en x̂4
formula-name-si5 = inyección del observador en x̂5
formula-name-l11 = ganancia del observador L = K/Ts, fila 1, columna 1
formula-name-l12 = ganancia del observador, fila 1, columna 2
formula-name-l21 = ganancia del observador, fila 2, columna 1
formula-name-l22 = ganancia del observador, fila 2, columna 2
formula-name-l31 = ganancia del observador, fila 3, columna 1
formula-name-l32 = ganancia del observador, fila 3, columna 2
formula-name-l41 = ganancia del observador, fila 4, columna 1
formula-name-l42 = ganancia del observador, fila 4, columna 2
formula-name-l51 = ganancia del observador, fila 5, columna 1
formula-name-l52 = ganancia del observador, fila 5, columna 2
formula-name-a1 = μ = 3·np·M/(2·J·Lr): a1·(x3·x̂4 − x2·x̂5) es el par dividido por J
formula-name-a2 = T0/J (la estimación â2 cuando el EKF estima la carga)
formula-name-a3 = Cf/J
formula-name-a5 = α·β, con α = Rr/Lr y β = M/(σ·Lr)
formula-name-a6 = np·β
formula-name-a7 = γ = Rs/σ + α·β·M
formula-name-a8 = α = Rr/Lr
formula-name-a9 = np
formula-name-a10 = α·M
formula-name-b = 1/σ
formula-name-da2 = derivada de â2 (su inyección) cuando el EKF estima la carga; si no, 0
formula-name-k1 = tasa del error de velocidad
formula-name-k2 = tasa del error de par (k2 = a7 + a8 + k2s1)
formula-name-k3 = tasa del error de flujo
formula-name-k4 = tasa del error de la derivada del flujo
formula-name-k1s1 = k1 − a3
formula-name-k2s1 = k2 − a7 − a8
formula-name-h2 = cota de |d̃2| de (38)
formula-name-eps2 = ε2 de (38)
formula-name-h4 = cota de |d̃4| de (53)
formula-name-eps4 = ε4 de (53)
formula-name-robust = 1 con los términos robustos (38) y (53) activados; si no, 0
formula-name-z1 = error de velocidad x̂1 − ω_d
formula-name-z3 = error de flujo x̂4² + x̂5² − ψ_d
formula-name-v1 = control virtual del paso 1 (el tuyo, si lo has escrito)
formula-name-z2 = error de par a1·(x3·x̂4 − x2·x̂5) − v1
formula-name-v3 = control virtual del paso 3 (el tuyo, si lo has escrito)
formula-name-z4 = error de la derivada del flujo 2·a10·(x2·x̂4 + x3·x̂5) − v3

## The functions a law may call: each one written with its arguments, and what it gives (the
## function's name and its arguments are the language's: keep them)

formula-function-sqrt = sqrt(x): raíz cuadrada
formula-function-exp = exp(x): exponencial
formula-function-ln = ln(x): logaritmo natural
formula-function-sin = sin(x): seno, x en rad
formula-function-cos = cos(x): coseno, x en rad
formula-function-tanh = tanh(x): tangente hiperbólica
formula-function-abs = abs(x): valor absoluto
formula-function-sign = sign(x): −1, 0 o 1
formula-function-atan2 = atan2(y, x): el ángulo de (x, y) (rad)
formula-function-min = min(a, b): el menor
formula-function-max = max(a, b): el mayor
formula-function-sat = sat(x, m): x limitado a [−m, m]
