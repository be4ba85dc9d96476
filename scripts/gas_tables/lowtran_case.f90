! SPDX-License-Identifier: Apache-2.0
! One LOWTRAN 7 transmittance run for make_gas_tables.py: a slant path from the ground to
! space through a model atmosphere without aerosol, written as one line per wavenumber.
!
! usage: lowtran_case MODEL ZENITH_DEG V1 V2 DV
!   MODEL  LOWTRAN model atmosphere 1-6 (tropical, mid-latitude summer, mid-latitude winter,
!          sub-arctic summer, sub-arctic winter, 1976 U.S. Standard)
!   ZENITH_DEG  zenith angle of the path at the ground, degrees
!   V1 V2 DV    wavenumbers, cm^-1
! Columns: wavenumber (cm^-1), then LOWTRAN's transmittances TX(5) (water continuum), TX(6)
! (molecular scattering), TX(8) (ultraviolet and visible ozone), TX(9) (total), TX(17)
! (water-vapour lines) and TX(31) (ozone band model; LOWTRAN copies TX(8) into it above
! 13,000 cm^-1).
program lowtran_case
    implicit none
    integer, parameter :: levels = 1
    integer :: model, nwl, i
    real :: v1, v2, dv, zenith
    character(64) :: arg
    real :: zmdl(levels), p(levels), t(levels), wmol(12)
    real, allocatable :: tx(:, :), v(:), alam(:), trace(:), unif(:), suma(:), irr(:, :), sumvv(:)

    if (command_argument_count() /= 5) error stop 'usage: lowtran_case MODEL ZENITH_DEG V1 V2 DV'
    call get_command_argument(1, arg); read (arg, *) model
    call get_command_argument(2, arg); read (arg, *) zenith
    call get_command_argument(3, arg); read (arg, *) v1
    call get_command_argument(4, arg); read (arg, *) v2
    call get_command_argument(5, arg); read (arg, *) dv
    nwl = nint((v2 - v1)/dv) + 1
    allocate (tx(nwl, 63), v(nwl), alam(nwl), trace(nwl), unif(nwl), suma(nwl), irr(nwl, 3), sumvv(nwl))
    zmdl = 0.0; p = 0.0; t = 0.0; wmol = 0.0
    ! Card 1: MODEL, ITYPE 3 (slant path to space), IEMSCT 0 (transmittance), IM 0;
    ! card 2 (set inside LWTRN7): no aerosol, no clouds; card 3: H1 = 0 km, H2 = 0 (space).
    call LWTRN7(.true., nwl, v1, v2, dv, tx, v, alam, trace, unif, suma, irr, sumvv, &
                model, 3, 0, 0, 0, levels, 0, zmdl, p, t, wmol, 0.0, 0.0, zenith, 0.0)
    do i = 1, nwl
        write (*, '(F9.1,6ES15.7)') v(i), tx(i, 5), tx(i, 6), tx(i, 8), tx(i, 9), tx(i, 17), tx(i, 31)
    end do
end program lowtran_case
